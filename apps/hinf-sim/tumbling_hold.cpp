// hinf-sim for `scenario: tumbling_hold` (docs/experiments.md "Seed 004"): the controller
// (read or synthesised), the Monte-Carlo runs, and the run directory: trajectory.csv,
// runs.csv, summary.json, controller.yaml, the three plots.
#include <filesystem>
#include <iostream>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/models/tumbling_hold.hpp"
#include "hinf/sim/hold_controller_source.hpp"
#include "hinf/sim/hold_report.hpp"
#include "hinf/sim/hold_run.hpp"
#include "hinf/sim/hold_scenario_yaml.hpp"
#include "hinf/sim/monte_carlo.hpp"
#include "hinf/sim/plots.hpp"
#include "hinf/sim/run.hpp"
#include "options.hpp"

namespace hinf::sim_cli {
namespace {

using namespace hinf::sim;

HoldSetup load_hold_setup(const Options& o, const std::string& text, HoldSummaryContext& context,
                          std::string& controller_yaml) {
  HoldSetup setup;
  setup.scenario = parse_hold_scenario(text, o.scenario_path);
  HoldScenario& s = setup.scenario;
  if (o.duration) {
    const double k = *o.duration / s.control_sample_time;
    if (std::abs(k - std::round(k)) > 1e-9 * k)
      throw hinf::Error(hinf::ErrorCode::InvalidInput, "--duration " + hinf::number_text(*o.duration) +
                                                           ": must be a whole multiple of control_sample_time " +
                                                           hinf::number_text(s.control_sample_time));
    s.duration = *o.duration;
    if (s.steady_state_start >= s.duration) s.steady_state_start = s.duration / 2;
  }
  ObtainedController c;
  try {
    c = obtain_hold_controller(s.controller, s.control_sample_time, status_log(o.verbose));
  } catch (const hinf::Error& e) {  // name a synthesis as such; a controller file names itself
    if (s.controller.synthesize_path.empty()) throw;
    throw hinf::Error(e.code(), std::string("synthesis: ") + e.what());
  }
  if (o.verbose) std::cerr << "hinf-sim: controller: " << c.origin << "\n";
  setup.controller = c.discrete;
  if (s.feedforward)
    setup.feedforward = hinf::models::equilibrium_force(s.servicer_mass, s.nominal_rate, s.nominal_accel, s.hold_point);
  context.scenario_path = o.scenario_path;
  context.seed = o.seed;
  context.controller_origin = c.origin;
  context.gamma = c.gamma;
  context.feedforward = setup.feedforward;
  controller_yaml = c.controller_yaml;
  return setup;
}

void write_hold_outputs(const Options& o, const HoldSetup& setup, const std::vector<HoldRunResult>& results,
                        const HoldSummaryContext& context, const std::string& controller_yaml) {
  namespace fs = std::filesystem;
  hinf::sim_cli::create_output_directory(o.out_dir);
  const HoldTrajectory& tr = *results.front().trajectory;
  hinf::AtomicFileSet outputs;
  outputs.protect(o.scenario_path);
  const auto at = [&](const char* name) { return (fs::path(o.out_dir) / name).string(); };
  outputs.add(at("trajectory.csv"), format_hold_trajectory_csv(tr));
  outputs.add(at("controller.yaml"), controller_yaml);
  outputs.add(at("runs.csv"), format_hold_runs_csv(results));
  outputs.add(at("summary.json"), format_hold_summary_json(setup.scenario, results, context));
  if (!o.no_plots && setup.scenario.plots)
    write_hold_plots(o.out_dir, tr, fs::path(o.scenario_path).stem().string(), outputs);
  outputs.commit();
}

}  // namespace

int run_tumbling_hold(const Options& o, const std::string& text) {
  HoldSummaryContext context;
  std::string controller_yaml;
  HoldSetup setup;
  std::vector<HoldRunResult> results(static_cast<std::size_t>(o.runs));
  return run_stages([&] { setup = load_hold_setup(o, text, context, controller_yaml); },
                    [&] {
                      for_each_run(
                          o.runs, o.jobs,
                          [&](long i) {
                            results[static_cast<std::size_t>(i)] = simulate_hold_run(setup, run_seed(o.seed, i), i == 0);
                          },
                          progress_bar(!o.quiet && o.runs > 1));
                    },
                    [&] { write_hold_outputs(o, setup, results, context, controller_yaml); });
}

}  // namespace hinf::sim_cli
