// verify / check / analyze of controller files (controller_files.hpp): reading and printing;
// the policies are synth::verify_controller and synth::compare_controller_with_golden.
#include "controller_files.hpp"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "hinf/certify/controller_certificate.hpp"
#include "hinf/common/error.hpp"
#include "hinf/runtime_yaml/controller_file.hpp"
#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/controller_regression.hpp"

namespace hinf::cli {
namespace {

struct ConfigAndController {
  synth::ControllerConfig config;
  runtime_yaml::ControllerFile file;
  hinf::Controller controller;
};

// The config and the controller file, the file's time domain and period checked against the config's.
ConfigAndController load(const std::string& config_path, const std::string& controller_path) {
  ConfigAndController in;
  in.config = synth::parse_controller_config(synth::read_config_bytes(config_path), config_path);
  in.file = runtime_yaml::load_controller_file(controller_path);
  const hinf::GeneralisedPlant& P = in.config.plant;
  const bool discrete = P.time == hinf::TimeDomain::Discrete;
  if (in.file.discrete != discrete)
    throw hinf::Error(hinf::ErrorCode::InvalidInput, controller_path + ": a " +
                                                         (in.file.discrete ? "discrete" : "continuous") +
                                                         "-time controller, but " + config_path + " is a " +
                                                         to_string(P.time) + "-time design");
  if (discrete && std::abs(*in.file.sample_time - P.sample_time) > 1e-12 * P.sample_time)
    throw hinf::Error(hinf::ErrorCode::InvalidInput, controller_path + ": sample_time " + num(*in.file.sample_time) +
                                                         " s, but the config's is " + num(P.sample_time) + " s");
  in.controller = {in.file.A_K, in.file.B_K, in.file.C_K, in.file.D_K};
  return in;
}

// The certificate's lines shared by verify and analyze.
void print_certificate(const synth::ControllerCertificate& c, bool discrete) {
  std::cout << "closed loop stable    " << (c.stable ? "yes" : "NO") << " ("
            << (discrete ? "spectral radius " : "spectral abscissa ") << num(c.stability_margin_value) << ")\n";
  if (!c.stable) return;
  std::cout << "closed-loop Hinf norm " << num(c.closed_loop_hinf_norm) << " at " << num(c.peak_frequency)
            << (discrete ? " rad/sample" : " rad/s") << "\n";
  std::cout << "largest pole modulus  " << num(c.max_pole_modulus) << (c.poles_in_disk ? "" : "  OUTSIDE the disk") << "\n";
  if (c.robust_channel_norm)
    std::cout << "robust channel        ‖T_qp‖∞ = " << num(*c.robust_channel_norm)
              << (c.robustly_stable ? " < 1 (small gain: robustly stable)" : " >= 1  FAIL") << "\n";
}

}  // namespace

bool is_controller_config(const std::string& path) {
  try {
    return synth::declares_controller(synth::read_config_bytes(path));
  } catch (const hinf::Error&) {
    return false;
  }
}

int verify_controller_file(const std::string& config_path, const std::string& controller_path) {
  const ConfigAndController in = load(config_path, controller_path);
  if (!in.file.gamma)
    throw hinf::Error(hinf::ErrorCode::InvalidInput, controller_path + ": no 'gamma' to verify (use 'analyze')");
  const synth::ControllerVerification v = synth::verify_controller(in.config, in.controller, *in.file.gamma);
  std::cout << "claimed gamma         " << num(*in.file.gamma) << "\n";
  print_certificate(v.certificate, in.file.discrete);
  std::cout << (v.holds ? std::string("verified: the controller file's gamma holds\n")
                        : "NOT verified" + (v.certificate.stable ? ": the closed loop's norm is " +
                                                                       num(v.certificate.closed_loop_hinf_norm) + "\n"
                                                                 : std::string(": the closed loop is unstable\n")));
  return v.holds ? 0 : 1;
}

int check_controller_file(const std::string& config_path, const std::string& golden_path, double rtol) {
  const ConfigAndController in = load(config_path, golden_path);
  if (!in.file.gamma) throw hinf::Error(hinf::ErrorCode::InvalidInput, golden_path + ": golden file has no 'gamma'");
  const synth::ControllerSynthesisResult now =
      synth::synthesize_controller(in.config.plant, in.config.settings, in.config.design);
  const synth::ControllerGoldenComparison cmp =
      synth::compare_controller_with_golden(in.config, in.controller, *in.file.gamma, now, rtol);
  std::cout << "gamma:      golden " << num(*in.file.gamma) << ", now " << num(now.gamma) << ", relative change "
            << num(cmp.gamma_relative_change) << (cmp.same_gamma ? "  ok" : "  CHANGED") << "\n"
            << "controller: "
            << (cmp.controller_difference ? "||K_golden - K_now||_inf / ||K_golden||_inf = " + num(*cmp.controller_difference) +
                                                " (transfer functions y -> u)"
                                          : std::string("an unstable controller: no transfer-function norm"))
            << (cmp.same_controller ? "  ok" : "  CHANGED") << "\n";
  if (cmp.golden_recertified)
    std::cout << "            the golden controller on this config: closed-loop Hinf norm "
              << num(cmp.golden_recertified->closed_loop_hinf_norm) << " at the golden gamma"
              << (cmp.golden_recertified->passed ? ": an equally optimal controller (the optimum is not unique)\n"
                                                 : ", certificate FAILED\n");
  if (!in.file.config_sha256.empty() && in.file.config_sha256 != in.config.sha256)
    std::cout << "note: the golden file was generated from a config with another sha256 ("
              << in.file.config_sha256.substr(0, 12) << "... vs " << in.config.sha256.substr(0, 12) << "...)\n";
  std::cout << (cmp.same() ? "same (rtol " + num(rtol) + ")\n" : "CHANGED (rtol " + num(rtol) + ")\n");
  return cmp.same() ? 0 : 1;
}

int analyze_controller_file(const std::string& config_path, const std::string& controller_path, bool json) {
  const ConfigAndController in = load(config_path, controller_path);
  // the certificate at the claimed γ (or at infinity: analysis only)
  const double gamma = in.file.gamma.value_or(INFINITY);
  const synth::ControllerCertificate c = certify::certify_controller(in.config.plant, in.controller, gamma, in.config.design.checks());
  if (json) {
    using Json = nlohmann::ordered_json;
    const auto number = [](double v) { return std::isfinite(v) ? Json(std::strtod(num(v).c_str(), nullptr)) : Json(nullptr); };
    Json j = Json::object();
    j["controller"] = controller_path;
    j["claimed_gamma"] = in.file.gamma ? number(*in.file.gamma) : Json(nullptr);
    j["closed_loop_stable"] = c.stable;
    j["stability_margin"] = number(c.stability_margin_value);
    j["closed_loop_hinf_norm"] = c.stable ? number(c.closed_loop_hinf_norm) : Json(nullptr);
    j["peak_frequency"] = c.stable ? number(c.peak_frequency) : Json(nullptr);
    j["max_pole_modulus"] = number(c.max_pole_modulus);
    j["robust_channel_hinf_norm"] = c.robust_channel_norm ? number(*c.robust_channel_norm) : Json(nullptr);
    std::cout << j.dump(-1, ' ', false, Json::error_handler_t::replace) << "\n";
    return 0;
  }
  std::cout << "controller            " << controller_path
            << (in.file.gamma ? " (claims gamma " + num(*in.file.gamma) + ")" : "") << "\n";
  print_certificate(c, in.file.discrete);
  return 0;
}

}  // namespace hinf::cli
