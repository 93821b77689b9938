// hinf-sim for `scenario: gyroless_attitude` (docs/experiments.md "Seed 002"): the Monte-Carlo
// runs of every configured augmented EKF (and every sweep entry) on each run's one
// star-tracker stream, and the run directory: trajectory.csv (run 0), runs.csv,
// summary.json and the plots of the source's Figs. 1–9.
#include <filesystem>
#include <iostream>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/sim/gyroless_report.hpp"
#include "hinf/sim/gyroless_run.hpp"
#include "hinf/sim/gyroless_scenario_yaml.hpp"
#include "hinf/sim/monte_carlo.hpp"
#include "hinf/sim/plots.hpp"
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

Campaign run_campaign(const Options& o, const GyrolessExperiment& e, std::vector<std::vector<GyrolessSample>>& samples) {
  Campaign stats(static_cast<std::size_t>(o.runs));
  for_each_run(
      o.runs, o.jobs,
      [&](long i) {
        GyrolessRunOptions options = e.options;
        if (i == 0)
          options.on_sample = [&samples](int f, const GyrolessSample& s) { samples[static_cast<std::size_t>(f)].push_back(s); };
        stats[static_cast<std::size_t>(i)] = run_gyroless(e.scenario, e.filters, options, run_seed(o.seed, i));
      },
      progress_bar(!o.quiet && o.runs > 1));
  return stats;
}

void write_outputs(const Options& o, const GyrolessExperiment& e,
                   const std::vector<std::vector<GyrolessSample>>& samples, const Campaign& stats) {
  namespace fs = std::filesystem;
  create_output_directory(o.out_dir);
  hinf::AtomicFileSet outputs;
  outputs.protect(o.scenario_path);
  const auto at = [&](const char* name) { return (fs::path(o.out_dir) / name).string(); };
  outputs.add(at("trajectory.csv"), format_gyroless_trajectory_csv(e, samples));
  std::vector<std::uint64_t> seeds;
  for (long i = 0; i < o.runs; ++i) seeds.push_back(run_seed(o.seed, i));
  outputs.add(at("runs.csv"), format_gyroless_runs_csv(e, stats, seeds));
  outputs.add(at("summary.json"), format_gyroless_summary_json(e, stats, o.scenario_path, o.seed));
  if (!o.no_plots && e.plots)
    write_gyroless_plots(o.out_dir, e, samples, fs::path(o.scenario_path).stem().string(), outputs);
  outputs.commit();
}

}  // namespace

int run_gyroless_attitude(const Options& o, const std::string& text) {
  GyrolessExperiment e;
  std::vector<std::vector<GyrolessSample>> samples;
  Campaign stats;
  return run_stages([&] { e = load_experiment(o, text); },
                    [&] {
                      samples.resize(e.filters.size());
                      stats = run_campaign(o, e, samples);
                    },
                    [&] { write_outputs(o, e, samples, stats); });
}

}  // namespace hinf::sim_cli
