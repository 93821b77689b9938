// The output files of a manoeuvring_target run directory (docs/experiments.md "Seed 001"):
// trajectory.csv (run 0, every filter), runs.csv and summary.json (every run) and the plots of
// the source's Figs. 4–5 (position, velocity and manoeuvre errors with ±3σ bands).
// Private to the family (its family.cpp reads the table; sim/src/stream_family.hpp).
#pragma once
#include <string>
#include <vector>

#include "hinf/sim/manoeuvring_run.hpp"
#include "hinf/sim/manoeuvring_scenario_yaml.hpp"
#include "stream_family.hpp"

namespace hinf::sim {

namespace families {

const StreamOutputs<ManoeuvringExperiment, ManoeuvringFilterStatistics, ManoeuvringSample>& manoeuvring_outputs();

}  // namespace families
}  // namespace hinf::sim
