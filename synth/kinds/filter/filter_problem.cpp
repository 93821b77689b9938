// The filter kind of the synthesis API (kinds.hpp): a config with `system:` or `hill:` — a
// robust H∞ filter by Theorem 1 or in observer form, chosen by the pipeline (synthesize.cpp,
// docs/maths.md §3, §18) — and its gains file (hinf-gains/1).
#include <utility>

#include "filter_report.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/filter_file.hpp"
#include "hinf/synth/gains_output.hpp"
#include "job_json.hpp"
#include "kinds.hpp"

namespace hinf::synth {
namespace {

class FilterProblem final : public ConfiguredProblem<SynthConfig> {
 public:
  using ConfiguredProblem::ConfiguredProblem;

  SolveOutcome solve(const JobObservers& observers) const override {
    if (observers.on_log) filter_report::log_before_solve(cfg_.plant, cfg_.settings, observers.on_log);
    SynthesisResult r = synthesize(cfg_.plant, settings_for(observers), observers.on_iteration);
    if (observers.on_log) filter_report::log_after_solve(r.solver, observers.on_log);
    return outcome("solve", filter_report::solve(r), std::move(r));
  }

  AnalysisOutcome analyze(const std::string& gains_path, const AnalysisOptions& options) const override {
    const Loaded in = load(gains_path);
    FilterAnalysis a = analyze_filter(cfg_.plant, cfg_.hill, cfg_.parameter_blocks, in.filter, cfg_.settings, options.delta_points);
    return {filter_report::analysis(gains_path, in.gains, a, cfg_.sample_time(), cfg_.plant.uncertain()),
            filter_report::analysis_json(cfg_.path, gains_path, in.gains, a, cfg_.sample_time()), std::move(a)};
  }

  VerifyOutcome verify(const std::string& gains_path) const override {
    const Loaded in = load(gains_path);
    const double gamma = stated_gamma(in.gains.gamma, gains_path + ": no 'gamma' to verify (use 'analyze' for a bound)");
    Verification v = verify_gains(cfg_, in.filter, gamma);
    return {v.holds, filter_report::verification(in.filter, gamma, v),
            filter_report::verification_json(cfg_.path, gains_path, in.filter, gamma, v), std::move(v)};
  }

  CheckOutcome check(const std::string& golden_path, double rtol, const JobObservers& observers) const override {
    const Loaded in = load(golden_path);
    const double gamma = stated_gamma(in.gains.gamma, golden_path + ": golden file has no 'gamma'");
    const SynthesisResult now = synthesize(cfg_.plant, settings_for(observers), observers.on_iteration);
    GoldenComparison cmp = compare_with_golden(cfg_, in.filter, gamma, now, rtol);
    return {cmp.same(), now.gamma, filter_report::check(in.gains, cfg_.sha256, now.gamma, cmp, rtol),
            filter_report::check_json(cfg_.path, golden_path, in.gains, in.filter, cfg_.sha256, now.gamma, cmp, rtol),
            std::move(cmp)};
  }

  SolveOutcome kalman() const override {
    SynthesisResult r = kalman_predictor(cfg_.plant, cfg_.settings, cfg_.kalman_noise);
    return outcome("kalman", filter_report::kalman(r), std::move(r));
  }

  DiscretiseOutcome discretise(const std::string& path, double, ControllerSampling method) const override {
    throw Error(ErrorCode::InvalidInput,
                std::string("--") + to_string(method) + ": " + cfg_.path + " is a filter config; a controller file (" +
                    path + ") is discretised against its controller config (controller:)",
                "config");
  }

  std::string export_sdpa() const override {
    return synthesis_sdpa(cfg_.plant, cfg_.settings,
                          "from " + cfg_.path + " (sha256 " + cfg_.sha256 + "), by hinf-synth " + tool_version() +
                              "\nminimise gamma^2; the SDPA dual objective is gamma*^2");
  }

 private:
  // solve's or kalman's outcome: the gains file, the report, the JSON.
  SolveOutcome outcome(const char* job, std::string report, SynthesisResult r) const {
    std::string file = format_gains_yaml(r, {cfg_.path, cfg_.sha256, cfg_.sample_time()});
    std::string json = job_json::solved(job, "filter", cfg_.path, r.gamma, "gains", file);
    return {r.gamma, std::move(file), "gains", std::move(report), std::move(json), std::move(r)};
  }
  struct Loaded {
    runtime_yaml::GainsFile gains;
    Filter filter;
  };
  Loaded load(const std::string& gains_path) const {
    runtime_yaml::GainsFile g = runtime_yaml::load_gains_file(gains_path);
    Filter f = filter_from_gains(g, cfg_.plant, gains_path);
    return {std::move(g), std::move(f)};
  }
};

bool declares_filter(const std::string&) { return true; }  // the registry's fallback kind

std::unique_ptr<Problem> parse_filter(const std::string& yaml_text, const std::string& source_name) {
  return std::make_unique<FilterProblem>(parse_config(yaml_text, source_name), filter_kind());
}

}  // namespace

const ProblemKind& filter_kind() {
  static const ProblemKind kind{"filter", &declares_filter, &parse_filter};
  return kind;
}

}  // namespace hinf::synth
