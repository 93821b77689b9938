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
// `key` optionally names the input that is wrong, so that a reader can point at it in the
// file (file:line:col) without parsing the message. Domain validators (a plant, a Hill
// model, the solver settings) know nothing of file syntax: they name the field as the
// maths or their struct does ("A", "chaser_mass") with `invalid_field`, and the reader
// that filled the struct re-keys the error to its own key path ("system.A",
// "hill.chaser_mass") with `rekeyed`.
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message, std::string key = std::string())
      : std::runtime_error(message), code_(code), key_(std::move(key)) {}
  // Error(InvalidInput) with the message field + detail (detail: " = -1: must be > 0").
  static Error invalid_field(const std::string& field, const std::string& detail) {
    return Error(ErrorCode::InvalidInput, field + detail, field, detail);
  }
  ErrorCode code() const { return code_; }
  const std::string& key() const { return key_; }
  // The same error naming `key_path` instead of the field (message key_path + detail);
  // an error not made by invalid_field keeps its message and takes the key.
  Error rekeyed(const std::string& key_path) const {
    if (!field_error_) return Error(code_, what(), key_path);
    return Error(code_, key_path + detail_, key_path, detail_);
  }

 private:
  Error(ErrorCode code, const std::string& message, std::string key, std::string detail)
      : std::runtime_error(message), code_(code), key_(std::move(key)), detail_(std::move(detail)),
        field_error_(true) {}
  ErrorCode code_;
  std::string key_;
  std::string detail_;
  bool field_error_ = false;
};

}  // namespace hinf
