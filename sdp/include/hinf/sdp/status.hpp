// How the interior-point method ended, with its message table. An internal fact of the
// solver, kept apart from hinf::ErrorCode (what the user sees).
#pragma once

namespace hinf::sdp {

enum class Status {
  Solved,          // certified relative gap below tolerance
  StoppedShort,    // phase II's end game failed on round-off: the last centred point, strictly
                   // feasible, is returned with its gap, which is above the tolerance (`detail`)
  Infeasible,      // phase I ended with a positive minimal violation (by the barrier's gap
                   // estimate; a theorem only once verified_infeasibility, dual_bound.hpp, verifies it)
  MaxIterations,   // Newton-iteration limit hit
  TimeLimit,       // wall-clock limit hit
  Interrupted,     // the caller asked to stop (Options::interrupted)
  NumericalError,  // the barrier could not be centred (round-off, engine failure)
  OutOfMemory,     // the Newton engine (Ipopt/MUMPS) could not get the memory it needs
  NotRun
};

const char* status_message(Status status);

// True when the solution holds a strictly feasible point the caller may use (and certify):
// Solved, or StoppedShort with its gap reported. The best point is never discarded.
inline bool has_point(Status status) { return status == Status::Solved || status == Status::StoppedShort; }

}  // namespace hinf::sdp
