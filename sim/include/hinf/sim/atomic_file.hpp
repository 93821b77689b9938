// Writing output files without ever leaving a partial one: write DIR/.NAME.tmp.PID, then
// rename it over DIR/NAME (rename is atomic on POSIX file systems).
#pragma once
#include <stdexcept>
#include <string>

namespace hinf::sim {

// Unwritable output (exit 2): names the path and the reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A unique temporary path in the directory of `final_path` (same file system).
std::string temporary_path_for(const std::string& final_path);
void write_file_atomic(const std::string& path, const std::string& content);
// Renames tmp → final; throws OutputError (and removes tmp) on failure.
void commit_file(const std::string& temporary, const std::string& final_path);

}  // namespace hinf::sim
