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
  if (o.duration) set_hold_duration(s, *o.duration);
  ObtainedController c;
  try {
    c = obtain_hold_controller(s.controller, s.control_sample_time, status_log(o.verbose));
  } catch (const hinf::Error& e) {  // name a synthesis as such; a controller file names itself
    if (s.controller.synthesize_path.empty()) throw;
    throw hinf::Error(e.code(), std::string("synthesis: ") + e.what());
  }
  if (o.verbose) std::cerr << "hinf-sim: controller: " << c.origin << "\n";
  setup.controller = c.discrete;
  if (s.feedforward) {
    setup.feedforward = hinf::models::equilibrium_force(s.servicer_mass, s.nominal_rate, s.nominal_accel, s.hold_point);
    if (!setup.feedforward.allFinite())
      throw hinf::Error(hinf::ErrorCode::InvalidInput,
                        o.scenario_path + ": feedforward: the equilibrium force U* (docs/maths.md (158)) is not finite "
                                          "for this servicer_mass, hold_point and feedforward rate_deg_s/accel_deg_s2");
  }
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
  const HoldTrajectory& tr = *results.front().trajectory;
  const ControllerSource& k = setup.scenario.controller;
  write_run_directory(o,
                      {{"trajectory.csv", format_hold_trajectory_csv(tr)},
                       {"controller.yaml", controller_yaml},
                       {"runs.csv", format_hold_runs_csv(results)},
                       {"summary.json", format_hold_summary_json(setup.scenario, results, context)}},
                      {k.file_path.empty() ? k.synthesize_path : k.file_path}, setup.scenario.plots,
                      [&](const std::string& title, hinf::AtomicFileSet& outputs) {
                        write_hold_plots(o.out_dir, tr, title, outputs);
                      });
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
