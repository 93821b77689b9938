// Reading a `scenario: tumbling_hold` file (docs/experiments.md, "Seed 004") with the
// project's strict YAML reader: unknown keys, bad values and inconsistent timing are
// hinf::Error(InvalidInput) naming file:line:col and the key path.
#pragma once
#include <string>

#include "hinf/sim/hold_scenario.hpp"

namespace hinf::sim {

HoldScenario parse_hold_scenario(const std::string& yaml_text, const std::string& source_name);

}  // namespace hinf::sim
