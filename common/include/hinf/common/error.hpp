// What went wrong, as a user sees it: one ErrorCode per process exit code, and the one
// exception type the libraries throw. Solver outcomes (hinf/sdp/status.hpp) are kept
// apart, as OSQP keeps its error enum apart from its solver status; the caller decides
// which ErrorCode an outcome amounts to.
#pragma once
#include <stdexcept>
#include <string>
#include <utility>

namespace hinf {

enum class ErrorCode {
  Ok = 0,
  CheckFailed,      // verify/check found a difference or an overstated bound   -> exit 1
  InvalidInput,     // bad config/gains file, bad option, unreadable/unwritable  -> exit 2
  Infeasible,       // ill-posed or infeasible problem (e.g. plant not Schur)     -> exit 3
  NumericalFailure  // solver or certificate failed numerically                   -> exit 4
};

const char* error_code_message(ErrorCode code);
// The process exit codes of the project: 0 ok, 1 check failed, 2 invalid input,
// 3 infeasible/ill-posed, 4 numerical failure.
int exit_code(ErrorCode code);

// The applications turn it into a message and the exit code of its ErrorCode. Nothing
// in the libraries aborts the process.
// `key` optionally names the input that is wrong as a key path ("hill.chaser_mass"), so that
// a reader can point at it in the file (file:line:col) without parsing the message.
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message, std::string key = std::string())
      : std::runtime_error(message), code_(code), key_(std::move(key)) {}
  ErrorCode code() const { return code_; }
  const std::string& key() const { return key_; }

 private:
  ErrorCode code_;
  std::string key_;
};

}  // namespace hinf
