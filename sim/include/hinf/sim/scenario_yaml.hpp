// Reading a scenario file (docs/experiments.md, "Scenario files"): strict YAML, an
// unknown key anywhere is an error naming the key path, with a did-you-mean.
#pragma once
#include <stdexcept>
#include <string>

#include "hinf/sim/scenario.hpp"

namespace hinf::sim {

// Any invalid scenario: the message names the file, the key path and the bad value.
class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Scenario load_scenario(const std::string& path);
// `source_name` is used in messages; relative paths inside resolve against its directory.
Scenario parse_scenario(const std::string& yaml_text, const std::string& source_name);

}  // namespace hinf::sim
