// `scenario: gyroless_attitude` (docs/experiments.md "Seed 002"): the Monte-Carlo runs of every
// configured augmented EKF (and every sweep entry) on each run's one star-tracker stream;
// trajectory.csv (run 0), runs.csv, summary.json and the plots of the source's Figs. 1–9.
#include "gyroless_report.hpp"

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
                                gyroless_outputs()});
  return family;
}

}  // namespace hinf::sim::families
