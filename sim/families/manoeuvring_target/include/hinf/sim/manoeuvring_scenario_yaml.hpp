// Reading a `scenario: manoeuvring_target` file (docs/experiments.md "Seed 001", which lists
// the keys) with the project's strict YAML reader: unknown keys, bad values, an
// orbit that is not elliptic or not above the Earth, and a manoeuvre or metric window outside
// the run are hinf::Error(InvalidInput) naming file:line:col and the key path.
#pragma once
#include <string>
#include <vector>

#include "hinf/sim/manoeuvring_run.hpp"
#include "hinf/sim/manoeuvring_scenario.hpp"

namespace hinf::sim {

// The most filters one scenario may run side by side.
constexpr int kMaxManoeuvringFilters = 16;

struct ManoeuvringExperiment {
  std::string path;
  ManoeuvringScenario scenario;
  std::vector<ManoeuvreFilterSettings> filters;  // in the file's order
  ManoeuvringRunOptions options;                 // estimate, windows, tolerance (on_sample unset)
  bool plots = true;
};

ManoeuvringExperiment parse_manoeuvring_scenario(const std::string& yaml_text, const std::string& source_name);

}  // namespace hinf::sim
