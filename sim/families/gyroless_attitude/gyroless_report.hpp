// The output files of a gyroless_attitude run directory (docs/experiments.md "Seed 002"):
// trajectory.csv (run 0, every filter), runs.csv and summary.json (every run) and the plots
// of the source's Figs. 1–9.
// Private to the family (its family.cpp reads the table; sim/src/stream_family.hpp).
#pragma once
#include <string>
#include <vector>

#include "hinf/sim/gyroless_run.hpp"
#include "hinf/sim/gyroless_scenario_yaml.hpp"
#include "stream_family.hpp"

namespace hinf::sim {

namespace families {

const StreamOutputs<GyrolessExperiment, GyrolessFilterStatistics, GyrolessSample>& gyroless_outputs();

}  // namespace families
}  // namespace hinf::sim
