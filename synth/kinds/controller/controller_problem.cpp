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
#include "hinf/synth/sampled_loop.hpp"
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
        certify::certify_controller(in.plant, in.controller, in.file.gamma.value_or(INFINITY), in.checks);
    return {controller_report::analysis(path, in.file.gamma, c, in.file.discrete),
            controller_report::analysis_json(cfg_.path, path, in.file.gamma, c), std::move(c)};
  }

  VerifyOutcome verify(const std::string& path) const override {
    const Loaded in = load(path);
    const double gamma = stated_gamma(in.file.gamma, path + ": no 'gamma' to verify (use 'analyze')");
    ControllerVerification v = verify_controller(in.plant, in.checks, in.controller, gamma);
    return {v.holds, controller_report::verification(gamma, v, in.file.discrete),
            controller_report::verification_json(cfg_.path, path, gamma, v, in.file.discrete,
                                                 in.checks.pole_disk_radius.has_value()),
            std::move(v)};
  }

  CheckOutcome check(const std::string& golden_path, double rtol, const JobObservers& observers) const override {
    const Loaded in = load(golden_path);
    if (in.file.discretised)
      throw Error(ErrorCode::InvalidInput, golden_path + ": a discretised controller (codegen --" +
                                               in.file.discretised->method + "); check compares a synthesis with its " +
                                               "continuous-time file");
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

  DiscretiseOutcome discretise(const std::string& path, double period, ControllerSampling method) const override {
    const std::string key = std::string("--") + to_string(method);
    require_sample_period(period, key);
    const runtime_yaml::ControllerFile file = runtime_yaml::load_controller_file(path);
    if (file.discrete) throw Error(ErrorCode::InvalidInput, key + ": " + path + " is already a discrete-time controller", key);
    if (cfg_.plant.time == TimeDomain::Discrete)
      throw Error(ErrorCode::InvalidInput, key + ": " + cfg_.path + " is a discrete-time design", key);
    if (file.config_sha256 != cfg_.sha256)
      throw Error(ErrorCode::InvalidInput,
                  key + ": " + path + " was synthesised from a config of sha256 " + file.config_sha256.substr(0, 12) +
                      "..., not from " + cfg_.path + " (sha256 " + cfg_.sha256.substr(0, 12) + "...): the sampled loop "
                      "is certified on the plant the controller was designed for",
                  "config");
    const Controller K{file.A_K, file.B_K, file.C_K, file.D_K};
    certify::require_controller_fits(cfg_.plant, K);
    const GeneralisedPlant sampled = sample_generalised_plant(cfg_.plant, period, key.c_str());
    DiscretisedController d{sample_controller(K, period, method), true, to_string(method), file.gamma, 0, {}};
    d.strictly_proper = d.controller.D_K.isZero(0);  // Tustin's D_d = D_K + (T/2) C_K M B_K (161)
    const certify::ControllerChecks checks = sampled_checks(period);
    // at γ = ∞: passed is the rest of the certificate (stable, robustly stable); the γ the file
    // states is its certified norm, at which it passes the same (norm ≤ γ)
    d.certificate = certify::certify_controller(sampled, d.controller, INFINITY, checks);
    DiscretiseOutcome out;
    out.holds = d.certificate.passed && std::isfinite(d.certificate.closed_loop_hinf_norm);
    if (out.holds) d.gamma = d.certificate.closed_loop_hinf_norm;
    out.gamma = d.gamma;
    if (out.holds) out.file = format_discretised_controller_yaml(d, sampled, {cfg_.path, cfg_.sha256, period});
    out.report = controller_report::discretised(path, period, method, file.gamma, out.holds, d.certificate);
    out.json = controller_report::discretised_json(cfg_.path, path, period, method, file.gamma, out.holds, d.certificate);
    out.certificate = std::move(d.certificate);
    return out;
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
  // A controller file with the plant and checks its certificate is computed on: the config's,
  // or — a controller discretised from this continuous design (codegen --tustin/--zoh) —
  // the config's plant sampled at the file's period (docs/maths.md (161b)).
  struct Loaded {
    runtime_yaml::ControllerFile file;
    Controller controller;
    GeneralisedPlant plant;
    certify::ControllerChecks checks;
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
    in.controller = {in.file.A_K, in.file.B_K, in.file.C_K, in.file.D_K};
    if (in.file.discretised && !discrete) {
      certify::require_controller_fits(P, in.controller);
      in.plant = sample_generalised_plant(P, *in.file.sample_time, "sample_time");
      in.checks = sampled_checks(*in.file.sample_time);
      return in;
    }
    in.plant = P;
    in.checks = cfg_.design.checks();
    if (in.file.discrete != discrete)
      throw Error(ErrorCode::InvalidInput, path + ": a " + (in.file.discrete ? "discrete" : "continuous") +
                                               "-time controller, but " + cfg_.path + " is a " + to_string(P.time) +
                                               "-time design");
    if (discrete && std::abs(*in.file.sample_time - P.sample_time) > 1e-12 * P.sample_time)
      throw Error(ErrorCode::InvalidInput, path + ": sample_time " + num(*in.file.sample_time) +
                                               " s, but the config's is " + num(P.sample_time) + " s");
    return in;
  }
  // The sampled loop's checks (docs/maths.md (161c)): the robust channel sampled with the
  // plant; a continuous design's pole disk is no region of the z-plane, and is not checked.
  certify::ControllerChecks sampled_checks(double period) const {
    certify::ControllerChecks c;
    if (cfg_.design.robust) c.robust = sample_channel(cfg_.plant, *cfg_.design.robust, period);
    return c;
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
