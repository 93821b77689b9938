// create_output_directory, write_run_directory (run_directory.hpp).
#include "hinf/sim/run_directory.hpp"

#include <filesystem>
#include <system_error>

#include "hinf/common/error.hpp"

namespace hinf::sim {

void create_output_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw hinf::Error(hinf::ErrorCode::InvalidInput, "cannot create the output directory '" + dir + "': " + ec.message());
}

void write_run_directory(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& files,
                         const std::vector<std::string>& inputs,
                         const std::function<void(hinf::AtomicFileSet& outputs)>& plots) {
  create_output_directory(dir);
  hinf::AtomicFileSet outputs;
  for (const std::string& input : inputs) outputs.protect(input);
  for (const auto& [name, content] : files) outputs.add((std::filesystem::path(dir) / name).string(), content);
  if (plots) plots(outputs);
  outputs.commit();
}

}  // namespace hinf::sim
