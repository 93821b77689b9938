// `scenario: tumbling_hold` (docs/experiments.md "Seed 004"): the controller (read or
// synthesised), the Monte-Carlo runs, and the run directory: trajectory.csv, runs.csv,
// summary.json, controller.yaml, the three plots.
#include <memory>

#include "families.hpp"
#include "hinf/common/error.hpp"
#include "hinf/models/tumbling_hold.hpp"
#include "hinf/sim/hold_controller_source.hpp"
#include "hinf/sim/hold_report.hpp"
#include "hinf/sim/hold_run.hpp"
#include "hinf/sim/hold_scenario_yaml.hpp"

namespace hinf::sim::families {
namespace {

// The scenario, its controller and the feedforward U*; what summary.json says of them.
HoldSetup load_hold(const CampaignRequest& r, HoldSummaryContext& context, std::string& controller_yaml) {
  HoldSetup setup;
  setup.scenario = parse_hold_scenario(r.scenario_text, r.scenario_path);
  HoldScenario& s = setup.scenario;
  if (r.duration) set_hold_duration(s, *r.duration);
  ObtainedController c;
  try {
    c = obtain_hold_controller(s.controller, s.control_sample_time, r.log);
  } catch (const hinf::Error& e) {  // name a synthesis as such; a controller file names itself
    if (s.controller.synthesize_path.empty()) throw;
    throw hinf::Error(e.code(), std::string("synthesis: ") + e.what());
  }
  if (r.log) r.log("controller: " + c.origin);
  setup.controller = c.discrete;
  if (s.feedforward) {
    setup.feedforward = hinf::models::equilibrium_force(s.servicer_mass, s.nominal_rate, s.nominal_accel, s.hold_point);
    if (!setup.feedforward.allFinite())
      throw hinf::Error(hinf::ErrorCode::InvalidInput,
                        r.scenario_path + ": feedforward: the equilibrium force U* (docs/maths.md (158)) is not finite "
                                          "for this servicer_mass, hold_point and feedforward rate_deg_s/accel_deg_s2");
  }
  context.scenario_path = r.scenario_path;
  context.seed = r.seed;
  context.controller_origin = c.origin;
  context.gamma = c.gamma;
  context.feedforward = setup.feedforward;
  controller_yaml = c.controller_yaml;
  return setup;
}

class TumblingHold final : public Family {
 public:
  const char* name() const override { return "tumbling_hold"; }
  void parse(const std::string& text, const std::string& path) const override { parse_hold_scenario(text, path); }
  CampaignResult simulate(const CampaignRequest& r) const override {
    HoldSummaryContext context;
    std::string controller_yaml;
    const HoldSetup setup = load_hold(r, context, controller_yaml);
    auto results = std::make_shared<std::vector<HoldRunResult>>(static_cast<std::size_t>(r.runs));
    for_each_run(
        r.runs, r.jobs,
        [&](long i) { (*results)[static_cast<std::size_t>(i)] = simulate_hold_run(setup, run_seed(r.seed, i), i == 0); },
        r.progress, r.interrupted);
    const HoldTrajectory& tr = *results->front().trajectory;
    const ControllerSource& k = setup.scenario.controller;
    CampaignResult out;
    out.files = {{"trajectory.csv", format_hold_trajectory_csv(tr)},
                 {"controller.yaml", controller_yaml},
                 {"runs.csv", format_hold_runs_csv(*results)},
                 {"summary.json", format_hold_summary_json(setup.scenario, *results, context)}};
    out.inputs = {k.file_path.empty() ? k.synthesize_path : k.file_path};
    out.plots = setup.scenario.plots;
    out.draw_plots = [results, scenario = setup.scenario, seed = r.seed, runs = r.runs](
                         const std::string& dir, const std::string& title, AtomicFileSet& outputs) {
      write_hold_plots(dir, *results->front().trajectory, plot_title(title, seed, runs), outputs);
      write_hold_error_band(dir, *results, scenario, plot_title(title, seed, runs), outputs);
    };
    return out;
  }
};

}  // namespace

const Family& tumbling_hold() {
  static const TumblingHold family;
  return family;
}

}  // namespace hinf::sim::families
