// hinf-sim for `scenario: gps_ins_relative` (docs/experiments.md "Seed 003"): the Monte-Carlo
// runs of every configured filter on each run's one measurement stream, and the run
// directory: trajectory.csv (run 0), runs.csv, summary.json.
#include <filesystem>
#include <iostream>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/sim/gps_ins_report.hpp"
#include "hinf/sim/gps_ins_run.hpp"
#include "hinf/sim/gps_ins_scenario_yaml.hpp"
#include "hinf/sim/monte_carlo.hpp"
#include "options.hpp"

namespace hinf::sim_cli {
namespace {

using namespace hinf::sim;

GpsInsExperiment load_experiment(const Options& o, const std::string& text) {
  GpsInsExperiment e = parse_gps_ins_scenario(text, o.scenario_path);
  if (o.duration) {
    const double k = *o.duration / e.scenario.sample_time;
    if (std::abs(k - std::round(k)) > 1e-9 * k || std::round(k) < 1)
      throw hinf::Error(hinf::ErrorCode::InvalidInput, "--duration " + hinf::number_text(*o.duration) +
                                                           ": must be a whole multiple of sample_time " +
                                                           hinf::number_text(e.scenario.sample_time));
    e.scenario.duration = *o.duration;
    e.options.window_end = std::min(e.options.window_end, e.scenario.duration);
    if (e.options.window_start >= e.options.window_end) e.options.window_start = e.options.window_end / 2;
  }
  return e;
}

void write_outputs(const Options& o, const GpsInsExperiment& e, const std::vector<std::vector<GpsInsSample>>& samples,
                   const std::vector<std::vector<GpsInsFilterStatistics>>& stats,
                   const std::vector<std::uint64_t>& seeds) {
  namespace fs = std::filesystem;
  create_output_directory(o.out_dir);
  hinf::AtomicFileSet outputs;
  outputs.protect(o.scenario_path);
  const auto at = [&](const char* name) { return (fs::path(o.out_dir) / name).string(); };
  outputs.add(at("trajectory.csv"), format_gps_ins_trajectory_csv(e, samples));
  outputs.add(at("runs.csv"), format_gps_ins_runs_csv(e, stats, seeds));
  outputs.add(at("summary.json"), format_gps_ins_summary_json(e, stats, o.scenario_path, o.seed));
  outputs.commit();
}

}  // namespace

int run_gps_ins(const Options& o, const std::string& text) {
  GpsInsExperiment e;
  try {
    e = load_experiment(o, text);
  } catch (const hinf::Error& err) {
    std::cerr << "hinf-sim: error: " << err.what() << "\n";
    return hinf::exit_code(err.code());
  }
  const std::size_t runs = static_cast<std::size_t>(o.runs);
  std::vector<std::vector<GpsInsFilterStatistics>> stats(runs);
  std::vector<std::uint64_t> seeds(runs);
  std::vector<std::vector<GpsInsSample>> samples(e.filters.size());
  try {
    for_each_run(
        o.runs, o.jobs,
        [&](long i) {
          const std::size_t r = static_cast<std::size_t>(i);
          seeds[r] = run_seed(o.seed, i);
          GpsInsRunOptions options = e.options;
          if (i == 0)
            options.on_sample = [&](int f, const GpsInsSample& s) { samples[static_cast<std::size_t>(f)].push_back(s); };
          stats[r] = run_gps_ins(e.scenario, e.filters, options, seeds[r]);
        },
        progress_bar(!o.quiet && o.runs > 1));
  } catch (const std::invalid_argument& err) {  // a runtime filter refusing its settings
    std::cerr << "hinf-sim: error: " << err.what() << "\n";
    return hinf::exit_code(hinf::ErrorCode::InvalidInput);
  }
  try {
    write_outputs(o, e, samples, stats, seeds);
  } catch (const hinf::Error& err) {
    std::cerr << "hinf-sim: error: " << err.what() << "\n";
    return hinf::exit_code(hinf::ErrorCode::InvalidInput);
  }
  return 0;
}

}  // namespace hinf::sim_cli
