// Error codes and solver statuses, kept apart (as in OSQP), each with a message table.
#pragma once
#include <stdexcept>
#include <string>

namespace hinf::synth {

// What went wrong, as seen by a user. Each maps to one process exit code.
enum class ErrorCode {
  Ok = 0,
  CheckFailed,      // verify/check found a difference or an overstated bound   -> exit 1
  InvalidInput,     // bad config/gains file, bad option, unreadable/unwritable  -> exit 2
  Infeasible,       // ill-posed or infeasible problem (e.g. plant not Schur)     -> exit 3
  NumericalFailure  // solver or certificate failed numerically                   -> exit 4
};

// How the interior-point solver ended. Kept apart from ErrorCode: a solver status
// is an internal fact; the caller decides which ErrorCode it amounts to.
enum class SolverStatus {
  Solved,              // relative gap below tolerance
  Infeasible,          // phase I converged with a positive minimal violation
  MaxIterations,       // iteration limit hit
  TimeLimit,           // wall-clock limit hit
  NumericalError,      // Ipopt failed or the barrier could not be centred
  NotRun
};

const char* error_code_message(ErrorCode code);
const char* solver_status_message(SolverStatus status);
int exit_code(ErrorCode code);

// The one exception type the library throws; the CLI turns it into a message and
// the exit code of its ErrorCode. Nothing in the library aborts the process.
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const { return code_; }

 private:
  ErrorCode code_;
};

}  // namespace hinf::synth
