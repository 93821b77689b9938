// hinf-sim for `scenario: gyroless_attitude` (docs/experiments.md "Seed 002"): the Monte-Carlo
// runs of every configured augmented EKF (and every sweep entry) on each run's one
// star-tracker stream, and the run directory: trajectory.csv (run 0), runs.csv,
// summary.json and the plots of the source's Figs. 1–9.
#include "hinf/sim/gyroless_report.hpp"
#include "hinf/sim/gyroless_run.hpp"
#include "hinf/sim/gyroless_scenario_yaml.hpp"
#include "options.hpp"

namespace hinf::sim_cli {
namespace {

using namespace hinf::sim;

GyrolessExperiment load_experiment(const Options& o, const std::string& text) {
  GyrolessExperiment e = parse_gyroless_scenario(text, o.scenario_path);
  if (o.duration) {
    e.scenario.duration = checked_duration(*o.duration, e.scenario.sample_time);
    if (e.options.window_start >= e.scenario.duration) e.options.window_start = e.scenario.duration / 2;
  }
  return e;
}

using Campaign = std::vector<std::vector<GyrolessFilterStatistics>>;  // [run][filter]

void write_outputs(const Options& o, const GyrolessExperiment& e,
                   const std::vector<std::vector<GyrolessSample>>& samples, const Campaign& stats) {
  write_run_directory(o,
                      {{"trajectory.csv", format_gyroless_trajectory_csv(e, samples)},
                       {"runs.csv", format_gyroless_runs_csv(e, stats, run_seeds(o.seed, o.runs))},
                       {"summary.json", format_gyroless_summary_json(e, stats, o.scenario_path, o.seed)}},
                      {}, e.plots, [&](const std::string& title, hinf::AtomicFileSet& outputs) {
                        write_gyroless_plots(o.out_dir, e, samples, title, outputs);
                      });
}

}  // namespace

int run_gyroless_attitude(const Options& o, const std::string& text) {
  GyrolessExperiment e;
  std::vector<std::vector<GyrolessSample>> samples;
  Campaign stats;
  return run_stages([&] { e = load_experiment(o, text); },
                    [&] {
                      samples.resize(e.filters.size());
                      stats = run_family_campaign<GyrolessFilterStatistics>(
                          o, &samples, [&](std::uint64_t seed, const std::function<void(int, const GyrolessSample&)>& on) {
                            GyrolessRunOptions options = e.options;
                            options.on_sample = on;
                            return run_gyroless(e.scenario, e.filters, options, seed);
                          });
                    },
                    [&] { write_outputs(o, e, samples, stats); });
}

}  // namespace hinf::sim_cli
