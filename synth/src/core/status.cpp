// Message tables and exit codes for ErrorCode and SolverStatus (status.hpp).
#include "hinf/synth/status.hpp"

namespace hinf::synth {

const char* error_code_message(ErrorCode code) {
  switch (code) {
    case ErrorCode::Ok: return "ok";
    case ErrorCode::CheckFailed: return "check failed";
    case ErrorCode::InvalidInput: return "invalid input";
    case ErrorCode::Infeasible: return "infeasible or ill-posed problem";
    case ErrorCode::NumericalFailure: return "numerical failure";
  }
  return "unknown error code";
}

const char* solver_status_message(SolverStatus status) {
  switch (status) {
    case SolverStatus::Solved: return "solved: relative gap below tolerance";
    case SolverStatus::Infeasible: return "infeasible: phase I ended with a positive minimal violation";
    case SolverStatus::MaxIterations: return "iteration limit reached";
    case SolverStatus::TimeLimit: return "time limit reached";
    case SolverStatus::NumericalError: return "numerical error: the barrier could not be centred";
    case SolverStatus::NotRun: return "not run";
  }
  return "unknown solver status";
}

// The process exit codes of the project: 0 ok, 1 check failed, 2 invalid input,
// 3 infeasible/ill-posed, 4 numerical failure.
int exit_code(ErrorCode code) {
  switch (code) {
    case ErrorCode::Ok: return 0;
    case ErrorCode::CheckFailed: return 1;
    case ErrorCode::InvalidInput: return 2;
    case ErrorCode::Infeasible: return 3;
    case ErrorCode::NumericalFailure: return 4;
  }
  return 4;  // an out-of-range enum value is itself an internal failure
}

}  // namespace hinf::synth
