// The controller kind of the synthesis API (kinds.hpp): a config with `controller:` — an
// output-feedback H∞ controller (docs/maths.md §26) — and its controller file
// (hinf-controller/1), read back with its time domain and period checked against the config.
#include <cmath>
#include <optional>
#include <utility>

#include "controller_report.hpp"
#include "hinf/certify/controller_certificate.hpp"
#include "hinf/common/error.hpp"
#include "hinf/runtime_yaml/controller_file.hpp"
#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/controller_output.hpp"
#include "job_json.hpp"
#include "kinds.hpp"
#include "report_text.hpp"

namespace hinf::synth {
namespace {

class ControllerProblem final : public ConfiguredProblem<ControllerConfig> {
 public:
  using ConfiguredProblem::ConfiguredProblem;

  SolveOutcome solve(const JobObservers& observers) const override {
    ControllerSynthesisResult r =
        synthesize_controller(cfg_.plant, settings_for(observers), cfg_.design, observers.on_iteration);
    std::string file = format_controller_yaml(r, cfg_.plant, cfg_.design, {cfg_.path, cfg_.sha256, period()});
    std::string json = job_json::solved("solve", "controller", cfg_.path, r.gamma, "controller", file);
    return {r.gamma, std::move(file), "controller", controller_report::solve(r, cfg_), std::move(json), std::move(r)};
  }

  AnalysisOutcome analyze(const std::string& path, const AnalysisOptions&) const override {
    const Loaded in = load(path);
    // the certificate at the claimed γ (or at infinity: analysis only)
    ControllerCertificate c =
        certify::certify_controller(cfg_.plant, in.controller, in.file.gamma.value_or(INFINITY), cfg_.design.checks());
    return {controller_report::analysis(path, in.file.gamma, c, in.file.discrete),
            controller_report::analysis_json(cfg_.path, path, in.file.gamma, c), std::move(c)};
  }

  VerifyOutcome verify(const std::string& path) const override {
    const Loaded in = load(path);
    const double gamma = stated_gamma(in.file.gamma, path + ": no 'gamma' to verify (use 'analyze')");
    ControllerVerification v = verify_controller(cfg_, in.controller, gamma);
    return {v.holds, controller_report::verification(gamma, v, in.file.discrete),
            controller_report::verification_json(cfg_.path, path, gamma, v, in.file.discrete, disk()), std::move(v)};
  }

  CheckOutcome check(const std::string& golden_path, double rtol, const JobObservers& observers) const override {
    const Loaded in = load(golden_path);
    const double gamma = stated_gamma(in.file.gamma, golden_path + ": golden file has no 'gamma'");
    const ControllerSynthesisResult now =
        synthesize_controller(cfg_.plant, settings_for(observers), cfg_.design, observers.on_iteration);
    ControllerGoldenComparison cmp = compare_controller_with_golden(cfg_, in.controller, gamma, now, rtol);
    return {cmp.same(), now.gamma,
            controller_report::check(gamma, in.file.config_sha256, cfg_.sha256, now.gamma, cmp, rtol),
            controller_report::check_json(cfg_.path, golden_path, gamma, in.file.config_sha256, cfg_.sha256, now.gamma,
                                          cmp, rtol, in.file.discrete, disk()),
            std::move(cmp)};
  }

  std::string export_sdpa() const override {
    return controller_sdpa(cfg_.plant, cfg_.design,
                           "from " + cfg_.path + " (sha256 " + cfg_.sha256 + "), by hinf-synth " + tool_version() +
                               "\nminimise the scaled gamma; the SDPA dual objective is its optimum");
  }

  SolveOutcome kalman() const override {
    throw Error(ErrorCode::InvalidInput,
                "kalman: " + cfg_.path + " declares a controller (controller:); the Kalman reference is of a filter "
                "config's plant (system: or hill:)", "controller");
  }

 private:
  struct Loaded {
    runtime_yaml::ControllerFile file;
    Controller controller;
  };
  bool disk() const { return cfg_.design.pole_disk_radius.has_value(); }
  std::optional<double> period() const {
    return cfg_.plant.time == TimeDomain::Discrete ? std::optional<double>(cfg_.plant.sample_time) : std::nullopt;
  }
  // The controller file, its time domain and period checked against the config's.
  Loaded load(const std::string& path) const {
    Loaded in;
    in.file = runtime_yaml::load_controller_file(path);
    const GeneralisedPlant& P = cfg_.plant;
    const bool discrete = P.time == TimeDomain::Discrete;
    if (in.file.discrete != discrete)
      throw Error(ErrorCode::InvalidInput, path + ": a " + (in.file.discrete ? "discrete" : "continuous") +
                                               "-time controller, but " + cfg_.path + " is a " + to_string(P.time) +
                                               "-time design");
    if (discrete && std::abs(*in.file.sample_time - P.sample_time) > 1e-12 * P.sample_time)
      throw Error(ErrorCode::InvalidInput, path + ": sample_time " + num(*in.file.sample_time) +
                                               " s, but the config's is " + num(P.sample_time) + " s");
    in.controller = {in.file.A_K, in.file.B_K, in.file.C_K, in.file.D_K};
    return in;
  }
};

std::unique_ptr<Problem> parse_controller(const std::string& yaml_text, const std::string& source_name) {
  return std::make_unique<ControllerProblem>(parse_controller_config(yaml_text, source_name), controller_kind());
}

}  // namespace

const ProblemKind& controller_kind() {
  static const ProblemKind kind{"controller", &declares_controller, &parse_controller};
  return kind;
}

}  // namespace hinf::synth
