// Reading a `scenario: gyroless_attitude` file (docs/experiments.md "Seed 002", which lists
// the keys) with the project's strict YAML reader: unknown keys, bad values and
// an inconsistent setup are hinf::Error(InvalidInput) naming file:line:col and the key path.
#pragma once
#include <string>
#include <vector>

#include "hinf/sim/gyroless_run.hpp"
#include "hinf/sim/gyroless_scenario.hpp"

namespace hinf::sim {

// The most filters one scenario may run side by side, sweeps included.
constexpr int kMaxGyrolessFilters = 32;

struct GyrolessExperiment {
  std::string path;
  GyrolessScenario scenario;
  // The named filters in the file's order, then each sweep's copies of its filter with Q
  // replaced (named `<filter>_q<Q>`, e.g. aekf_q1e-18).
  std::vector<GyrolessFilterSettings> filters;
  GyrolessRunOptions options;  // window start, initial estimate (on_sample unset)
  bool plots = true;
};

GyrolessExperiment parse_gyroless_scenario(const std::string& yaml_text, const std::string& source_name);

}  // namespace hinf::sim
