// `scenario: manoeuvring_target` (docs/experiments.md "Seed 001"): the Monte-Carlo runs of every
// configured transient-model manoeuvre estimator on each run's one measurement stream;
// trajectory.csv (run 0), runs.csv, summary.json and the plots of the source's Figs. 4–5.
#include "hinf/sim/manoeuvring_report.hpp"
#include "hinf/sim/manoeuvring_run.hpp"
#include "hinf/sim/manoeuvring_scenario_yaml.hpp"
#include "stream_family.hpp"

namespace hinf::sim::families {
namespace {

void shorten_manoeuvring(ManoeuvringExperiment& e, double duration) { e.scenario.duration = duration; }

using Manoeuvring = StreamFamily<ManoeuvringExperiment, ManoeuvringFilterStatistics, ManoeuvringSample>;

}  // namespace

const Family& manoeuvring_target() {
  static const Manoeuvring family({"manoeuvring_target", parse_manoeuvring_scenario, shorten_manoeuvring,
                                   run_manoeuvring, format_manoeuvring_trajectory_csv,
                                   format_manoeuvring_runs_csv, format_manoeuvring_summary_json,
                                   write_manoeuvring_plots});
  return family;
}

}  // namespace hinf::sim::families
