// Message table of sdp::Status (status.hpp).
#include "hinf/sdp/status.hpp"

namespace hinf::sdp {

const char* status_message(Status status) {
  switch (status) {
    case Status::Solved: return "solved: relative gap below tolerance";
    case Status::StoppedShort: return "stopped short of the gap tolerance: the last centred point, its gap reported";
    case Status::Infeasible: return "infeasible: phase I ended with a positive minimal violation";
    case Status::MaxIterations: return "iteration limit reached";
    case Status::TimeLimit: return "time limit reached";
    case Status::Interrupted: return "interrupted";
    case Status::NumericalError: return "numerical error: the barrier could not be centred";
    case Status::OutOfMemory: return "out of memory: the Newton engine (Ipopt/MUMPS) could not allocate its workspace";
    case Status::NotRun: return "not run";
  }
  return "unknown solver status";
}

}  // namespace hinf::sdp
