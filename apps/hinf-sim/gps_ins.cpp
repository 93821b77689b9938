// hinf-sim for `scenario: gps_ins_relative` (docs/experiments.md "Seed 003"): the Monte-Carlo
// runs of every configured filter on each run's one measurement stream, and the run
// directory: trajectory.csv (run 0), runs.csv, summary.json, the plots of Figs. 1–4 and, with
// metrics.table1_products_fractions, table1.csv (one campaign per fraction, same seeds).
#include <filesystem>
#include <iostream>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/sim/gps_ins_report.hpp"
#include "hinf/sim/gps_ins_run.hpp"
#include "hinf/sim/gps_ins_scenario_yaml.hpp"
#include "hinf/sim/monte_carlo.hpp"
#include "hinf/sim/plots.hpp"
#include "options.hpp"

namespace hinf::sim_cli {
namespace {

using namespace hinf::sim;

GpsInsExperiment load_experiment(const Options& o, const std::string& text) {
  GpsInsExperiment e = parse_gps_ins_scenario(text, o.scenario_path);
  if (o.duration) {
    e.scenario.duration = checked_duration(*o.duration, e.scenario.sample_time);
    e.options.window_end = std::min(e.options.window_end, e.scenario.duration);
    if (e.options.window_start >= e.options.window_end) e.options.window_start = e.options.window_end / 2;
  }
  return e;
}

using Campaign = std::vector<std::vector<GpsInsFilterStatistics>>;  // [run][filter]

// The Monte-Carlo runs of `scenario`; run 0's samples into `samples` when given.
Campaign run_campaign(const Options& o, const GpsInsExperiment& e, const GpsInsScenario& scenario,
                      std::vector<std::vector<GpsInsSample>>* samples) {
  return run_family_campaign<GpsInsFilterStatistics, GpsInsSample>(
      o, samples, [&](std::uint64_t seed, const std::function<void(int, const GpsInsSample&)>& on) {
        GpsInsRunOptions options = e.options;
        options.on_sample = on;
        return run_gps_ins(scenario, e.filters, options, seed);
      });
}

// One campaign per table-1 fraction; the scenario's own campaign where the fraction is its own.
std::vector<Campaign> run_table1_campaigns(const Options& o, const GpsInsExperiment& e, const Campaign& own) {
  std::vector<Campaign> campaigns;
  for (double p : e.table1_fractions) {
    if (p == e.scenario.inertia_products_fraction) {
      campaigns.push_back(own);
      continue;
    }
    GpsInsScenario scenario = e.scenario;
    scenario.inertia_products_fraction = p;
    campaigns.push_back(run_campaign(o, e, scenario, nullptr));
  }
  return campaigns;
}

void write_outputs(const Options& o, const GpsInsExperiment& e, const std::vector<std::vector<GpsInsSample>>& samples,
                   const Campaign& stats, const std::vector<Campaign>& table1) {
  std::vector<std::pair<std::string, std::string>> files{
      {"trajectory.csv", format_gps_ins_trajectory_csv(e, samples)},
      {"runs.csv", format_gps_ins_runs_csv(e, stats, run_seeds(o.seed, o.runs))},
      {"summary.json", format_gps_ins_summary_json(e, stats, o.scenario_path, o.seed)}};
  if (!e.table1_fractions.empty()) files.emplace_back("table1.csv", format_gps_ins_table1_csv(e, e.table1_fractions, table1));
  write_run_directory(o, files, {}, e.plots, [&](const std::string& title, hinf::AtomicFileSet& outputs) {
    write_gps_ins_plots(o.out_dir, e, samples, title, outputs);
  });
}

}  // namespace

int run_gps_ins(const Options& o, const std::string& text) {
  GpsInsExperiment e;
  std::vector<std::vector<GpsInsSample>> samples;
  Campaign stats;
  std::vector<Campaign> table1;
  return run_stages([&] { e = load_experiment(o, text); },
                    [&] {
                      samples.resize(e.filters.size());
                      stats = run_campaign(o, e, e.scenario, &samples);
                      table1 = run_table1_campaigns(o, e, stats);
                    },
                    [&] { write_outputs(o, e, samples, stats, table1); });
}

}  // namespace hinf::sim_cli
