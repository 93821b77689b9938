// A file named inside a scenario (gains file, synthesis config, controller file): relative
// paths resolve against the scenario file's directory; a missing file is Error(InvalidInput)
// naming the key.
#pragma once
#include <filesystem>
#include <string>

#include "hinf/common/yaml_reader.hpp"

namespace hinf::sim {

inline std::string resolve_scenario_file(const YamlMap& n, const std::string& key, const std::string& scenario_path) {
  std::filesystem::path p(n.word(key));
  if (p.is_relative()) p = std::filesystem::path(scenario_path).parent_path() / p;
  if (!std::filesystem::exists(p))
    n.fail(key, "file '" + p.string() +
                    "' does not exist (relative paths resolve against the scenario file's directory)");
  return p.lexically_normal().string();
}

}  // namespace hinf::sim
