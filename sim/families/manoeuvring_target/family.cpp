// `scenario: manoeuvring_target` (docs/experiments.md "Seed 001"): the Monte-Carlo runs of every
// configured transient-model manoeuvre estimator on each run's one measurement stream;
// trajectory.csv (run 0), runs.csv, summary.json and the plots of the source's Figs. 4–5.
#include "manoeuvring_report.hpp"

namespace hinf::sim::families {
namespace {

void shorten_manoeuvring(ManoeuvringExperiment& e, double duration) { e.scenario.duration = duration; }

using Manoeuvring = StreamFamily<ManoeuvringExperiment, ManoeuvringFilterStatistics, ManoeuvringSample>;

}  // namespace

const Family& manoeuvring_target() {
  static const Manoeuvring family({"manoeuvring_target", parse_manoeuvring_scenario, shorten_manoeuvring,
                                   run_manoeuvring, manoeuvring_outputs()});
  return family;
}

}  // namespace hinf::sim::families
