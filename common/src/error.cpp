// Message table and exit codes of ErrorCode (error.hpp).
#include "hinf/common/error.hpp"

namespace hinf {

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

}  // namespace hinf
