// The output files of a linear_plant run directory (docs/experiments.md "The user's own
// plant"): trajectory.csv (run 0: z, each filter's ẑ and z − ẑ), runs.csv and summary.json
// (every run; each filter's predicted RMS beside the measured one), each filter's gains file
// (<name>_gains.yaml, family.cpp) and error.png (run 0).
// Private to the family (its family.cpp reads the table; sim/src/stream_family.hpp).
#pragma once
#include "hinf/sim/linear_plant_run.hpp"
#include "hinf/sim/linear_plant_scenario_yaml.hpp"
#include "stream_family.hpp"

namespace hinf::sim::families {

const StreamOutputs<LinearPlantExperiment, LinearPlantStatistics, LinearPlantSample>& linear_plant_outputs();

}  // namespace hinf::sim::families
