// hinf-sim for `scenario: manoeuvring_target` (docs/experiments.md "Seed 001"): the Monte-Carlo
// runs of every configured transient-model manoeuvre estimator on each run's one measurement
// stream, and the run directory: trajectory.csv (run 0), runs.csv, summary.json and the plots
// of the source's Figs. 4–5.
#include "hinf/sim/manoeuvring_report.hpp"
#include "hinf/sim/manoeuvring_run.hpp"
#include "hinf/sim/manoeuvring_scenario_yaml.hpp"
#include "options.hpp"

namespace hinf::sim_cli {
namespace {

using namespace hinf::sim;

ManoeuvringExperiment load_experiment(const Options& o, const std::string& text) {
  ManoeuvringExperiment e = parse_manoeuvring_scenario(text, o.scenario_path);
  if (o.duration) e.scenario.duration = checked_duration(*o.duration, e.scenario.sample_time);
  return e;
}

using Campaign = std::vector<std::vector<ManoeuvringFilterStatistics>>;  // [run][filter]

void write_outputs(const Options& o, const ManoeuvringExperiment& e,
                   const std::vector<std::vector<ManoeuvringSample>>& samples, const Campaign& stats) {
  write_run_directory(o,
                      {{"trajectory.csv", format_manoeuvring_trajectory_csv(e, samples)},
                       {"runs.csv", format_manoeuvring_runs_csv(e, stats, run_seeds(o.seed, o.runs))},
                       {"summary.json", format_manoeuvring_summary_json(e, stats, o.scenario_path, o.seed)}},
                      {}, e.plots, [&](const std::string& title, hinf::AtomicFileSet& outputs) {
                        write_manoeuvring_plots(o.out_dir, e, samples, title, outputs);
                      });
}

}  // namespace

int run_manoeuvring_target(const Options& o, const std::string& text) {
  ManoeuvringExperiment e;
  std::vector<std::vector<ManoeuvringSample>> samples;
  Campaign stats;
  return run_stages([&] { e = load_experiment(o, text); },
                    [&] {
                      samples.resize(e.filters.size());
                      stats = run_family_campaign<ManoeuvringFilterStatistics>(
                          o, &samples, [&](std::uint64_t seed, const std::function<void(int, const ManoeuvringSample&)>& on) {
                            ManoeuvringRunOptions options = e.options;
                            options.on_sample = on;
                            return run_manoeuvring(e.scenario, e.filters, options, seed);
                          });
                    },
                    [&] { write_outputs(o, e, samples, stats); });
}

}  // namespace hinf::sim_cli
