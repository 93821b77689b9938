// Reading a scenario file (docs/experiments.md, "Scenario files") with the strict YAML
// reader of configs and gains files (hinf::YamlReader): an unknown key anywhere is an
// error naming the key path, with a did-you-mean.
#pragma once
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/sim/scenario.hpp"

namespace hinf::sim {

// Any unreadable or invalid scenario throws hinf::Error (InvalidInput, exit code 2); the
// message names the file:line:col, the key path and the bad value.
Scenario load_scenario(const std::string& path);
// `source_name` is used in messages; relative paths inside resolve against its directory.
Scenario parse_scenario(const std::string& yaml_text, const std::string& source_name);

}  // namespace hinf::sim
