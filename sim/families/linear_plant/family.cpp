// `scenario: linear_plant` (docs/experiments.md "The user's own plant"): the plant of the
// user's synthesis config under white noise, the H∞ filter and the Kalman predictor of it (and
// gains files) side by side over Monte-Carlo runs; trajectory.csv (run 0), runs.csv,
// summary.json, each filter's gains file and error.png.
#include <algorithm>

#include "linear_plant_report.hpp"

namespace hinf::sim::families {
namespace {

using LinearPlant = StreamFamily<LinearPlantExperiment, LinearPlantStatistics, LinearPlantSample>;

void shorten_linear_plant(LinearPlantExperiment& e, double duration) {
  e.scenario.duration = duration;
  e.options.window_start = std::min(e.options.window_start, duration / 2);
}

// <name>_gains.yaml: the gains each filter flew (a file's bytes, or the synthesis library's writer).
void gains_files(const CampaignRequest&, const LinearPlantExperiment& e, const LinearPlant::Functions::Campaign&,
                 std::vector<std::pair<std::string, std::string>>& files) {
  for (const LinearPlantFilter& f : e.filters) files.emplace_back(f.name + "_gains.yaml", f.gains_yaml);
}

std::vector<std::string> inputs(const LinearPlantExperiment& e) { return e.inputs; }

}  // namespace

const Family& linear_plant() {
  static const LinearPlant family({"linear_plant", parse_linear_plant_scenario, shorten_linear_plant,
                                   run_linear_plant, linear_plant_outputs(), gains_files, inputs});
  return family;
}

}  // namespace hinf::sim::families
