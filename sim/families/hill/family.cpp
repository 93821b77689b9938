// The Hill/CW experiments (no `scenario:` key; docs/experiments.md "Seed 000"): the H∞ filter
// (gains read or synthesised), the paper's published gains, the EKFs and the REKF on one
// nonlinear truth per run; trajectory.csv, runs.csv, summary.json, the gains files and plots.
#include <memory>

#include "families.hpp"
#include "hinf/common/error.hpp"
#include "hinf/sim/gains_source.hpp"
#include "hinf/sim/plots.hpp"
#include "hinf/sim/report.hpp"
#include "hinf/sim/run.hpp"
#include "hinf/sim/scenario_yaml.hpp"

namespace hinf::sim::families {
namespace {

using NamedFile = std::pair<std::string, std::string>;

// --duration: a whole number of sample times; the steady-state window shrinks with it.
void override_duration(Scenario& s, std::optional<double> duration) {
  if (!duration) return;
  s.duration = checked_duration(*duration, s.sample_time);
  if (s.steady_state_start && *s.steady_state_start > s.duration) s.steady_state_start.reset();
}

// The gains of one LTI filter ("hinf" or "published"), read or synthesised; hinf-sim feeds it
// y = Cartesian position (m = 3) and reads the whole state (l = 6).
ObtainedGains obtain_filter_gains(const CampaignRequest& r, const LtiGainsSource& src, const std::string& name) {
  ObtainedGains g;
  try {
    g = obtain_gains(src, r.log);
  } catch (const hinf::Error& e) {  // name a synthesis as such; a gains file names itself
    if (src.synthesize_path.empty()) throw;
    throw hinf::Error(e.code(), std::string("synthesis: ") + e.what());
  }
  if (g.gains.B_F.cols() != 3 || g.gains.C_F.rows() != 6)
    throw hinf::Error(hinf::ErrorCode::InvalidInput,
                      "filters." + name + ": " + g.origin + ": B_F has " + std::to_string(g.gains.B_F.cols()) +
                          " columns and C_F " + std::to_string(g.gains.C_F.rows()) +
                          " rows; hinf-sim needs m = 3 (Cartesian position measured) and l = 6 (L = I6)");
  if (r.log) r.log(name + ": " + g.origin);
  return g;
}

// The scenario and the gains of its LTI filters; the gains files to write beside the run's
// outputs (file name, content) and what summary.json says of them.
RunSetup load_hill(const CampaignRequest& r, SummaryContext& context, std::vector<NamedFile>& gains_files) {
  RunSetup setup;
  setup.scenario = parse_scenario(r.scenario_text, r.scenario_path);
  override_duration(setup.scenario, r.duration);
  for (const bool hinf : {true, false}) {
    const auto& src = hinf ? setup.scenario.filters.hinf : setup.scenario.filters.published;
    if (!src) continue;
    const std::string name = hinf ? "hinf" : "published";
    const ObtainedGains g = obtain_filter_gains(r, *src, name);
    (hinf ? setup.hinf : setup.published) = g.gains;
    context.gains[name] = {g.origin, g.gamma};
    gains_files.emplace_back(hinf ? "gains.yaml" : "published_gains.yaml", g.gains_yaml);
  }
  return setup;
}

class Hill final : public Family {
 public:
  const char* name() const override { return ""; }
  void parse(const std::string& text, const std::string& path) const override { parse_scenario(text, path); }
  CampaignResult simulate(const CampaignRequest& r) const override {
    SummaryContext context;
    context.scenario_path = r.scenario_path;
    context.seed = r.seed;
    std::vector<NamedFile> gains_files;
    const RunSetup setup = load_hill(r, context, gains_files);
    const auto results =
        std::make_shared<const std::vector<RunResult>>(run_monte_carlo(setup, r.runs, r.seed, r.jobs, r.progress, r.interrupted));
    CampaignResult out;
    out.files = {{"trajectory.csv", format_trajectory_csv(*results->front().trajectory)}};
    out.files.insert(out.files.end(), gains_files.begin(), gains_files.end());
    out.files.push_back({"runs.csv", format_runs_csv(*results)});
    out.files.push_back({"summary.json", format_summary_json(setup.scenario, *results, context)});
    for (const auto& src : {setup.scenario.filters.hinf, setup.scenario.filters.published})
      if (src) out.inputs.push_back(src->gains_path.empty() ? src->synthesize_path : src->gains_path);
    out.plots = setup.scenario.plots;
    const auto scenario = std::make_shared<const Scenario>(setup.scenario);
    out.draw_plots = [results, scenario, seed = r.seed](const std::string& dir, const std::string& title,
                                                         AtomicFileSet& outputs) {
      write_plots(dir, *results, *scenario, title, seed, outputs);
    };
    return out;
  }
};

}  // namespace

const Family& hill() {
  static const Hill family;
  return family;
}

}  // namespace hinf::sim::families
