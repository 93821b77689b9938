// create_output_directory, write_run_directory (run_directory.hpp).
#include "hinf/sim/run_directory.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <system_error>

#include "hinf/common/error.hpp"

namespace hinf::sim {

void create_output_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw hinf::Error(hinf::ErrorCode::InvalidInput, "cannot create the output directory '" + dir + "': " + ec.message());
}

namespace {

namespace fs = std::filesystem;

// A name a manifest may list: a file directly in the run directory, not the manifest itself.
bool plain_file_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
         name.find('\0') == std::string::npos && name != kManifestName;
}

// The names an earlier run's manifest lists (comment lines and anything but plain names
// skipped), or nullopt if the directory has no manifest.
std::optional<std::vector<std::string>> read_manifest(const fs::path& dir) {
  std::ifstream in(dir / kManifestName);
  if (!in) return std::nullopt;
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line.front() != '#' && plain_file_name(line)) names.push_back(line);
  return names;
}

std::string manifest_text(const std::vector<std::string>& names) {
  std::string text = std::string(kManifestHeader) + "\n";
  for (const std::string& name : names) text += name + "\n";
  return text;
}

bool is_input(const fs::path& file, const std::vector<std::string>& inputs) {
  std::error_code ec;
  return std::any_of(inputs.begin(), inputs.end(), [&](const std::string& in) { return fs::equivalent(file, in, ec); });
}

// Removes the previous run's files that this run did not write; returns their names.
std::vector<std::string> remove_stale(const fs::path& dir, const std::vector<std::string>& previous,
                                      const std::vector<std::string>& written, const std::vector<std::string>& inputs) {
  std::vector<std::string> removed;
  for (const std::string& name : previous) {
    if (std::find(written.begin(), written.end(), name) != written.end()) continue;
    const fs::path file = dir / name;
    std::error_code ec;
    if (!fs::is_regular_file(fs::symlink_status(file, ec)) || is_input(file, inputs)) continue;
    if (fs::remove(file, ec)) removed.push_back(name);
  }
  return removed;
}

}  // namespace

RunDirectoryReplaced write_run_directory(const std::string& dir,
                                         const std::vector<std::pair<std::string, std::string>>& files,
                                         const std::vector<std::string>& inputs,
                                         const std::function<void(hinf::AtomicFileSet& outputs)>& plots) {
  create_output_directory(dir);
  const std::optional<std::vector<std::string>> previous = read_manifest(dir);
  hinf::AtomicFileSet outputs;
  for (const std::string& input : inputs) outputs.protect(input);
  for (const auto& [name, content] : files) outputs.add((fs::path(dir) / name).string(), content);
  if (plots) plots(outputs);
  std::vector<std::string> written;
  for (const std::string& target : outputs.targets()) written.push_back(fs::path(target).filename().string());
  outputs.add((fs::path(dir) / kManifestName).string(), manifest_text(written));
  outputs.commit();
  RunDirectoryReplaced replaced;
  replaced.previous_run = previous.has_value();
  if (previous) replaced.removed = remove_stale(dir, *previous, written, inputs);
  return replaced;
}

}  // namespace hinf::sim
