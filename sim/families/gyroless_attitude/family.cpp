// `scenario: gyroless_attitude` (docs/experiments.md "Seed 002"): the Monte-Carlo runs of every
// configured augmented EKF (and every sweep entry) on each run's one star-tracker stream;
// trajectory.csv (run 0), runs.csv, summary.json and the plots of the source's Figs. 1–9.
#include "hinf/sim/gyroless_report.hpp"
#include "hinf/sim/gyroless_run.hpp"
#include "hinf/sim/gyroless_scenario_yaml.hpp"
#include "stream_family.hpp"

namespace hinf::sim::families {
namespace {

void shorten_gyroless(GyrolessExperiment& e, double duration) {
  e.scenario.duration = duration;
  if (e.options.window_start >= duration) e.options.window_start = duration / 2;
}

using Gyroless = StreamFamily<GyrolessExperiment, GyrolessFilterStatistics, GyrolessSample>;

}  // namespace

const Family& gyroless_attitude() {
  static const Gyroless family({"gyroless_attitude", parse_gyroless_scenario, shorten_gyroless, run_gyroless,
                                format_gyroless_trajectory_csv, format_gyroless_runs_csv, format_gyroless_summary_json,
                                write_gyroless_plots});
  return family;
}

}  // namespace hinf::sim::families
