// Reading a `scenario: linear_plant` file (docs/experiments.md "The user's own plant", which
// lists the keys) with the project's strict YAML reader; the synthesis config it names is read
// with the synthesis library's reader, and each filter's gains are obtained then (a gains
// file read, the H∞ filter synthesised, the Kalman predictor computed). Errors are
// hinf::Error with their own code: InvalidInput naming file:line:col and the key path, or a
// synthesis's Infeasible / NumericalFailure.
#pragma once
#include <string>
#include <vector>

#include "hinf/sim/linear_plant_run.hpp"

namespace hinf::sim {

// The most filters one scenario may run side by side.
constexpr int kMaxLinearPlantFilters = 16;

struct LinearPlantExperiment {
  std::string path;
  LinearPlantScenario scenario;
  std::vector<LinearPlantFilter> filters;  // in the file's order
  LinearPlantRunOptions options;          // the window start (on_sample unset)
  std::vector<std::string> inputs;        // the files read: the config, the gains files
  bool plots = true;
};

LinearPlantExperiment parse_linear_plant_scenario(const std::string& yaml_text, const std::string& source_name);

}  // namespace hinf::sim
