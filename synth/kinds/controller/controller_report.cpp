// The controller kind's reports (controller_report.hpp).
#include "controller_report.hpp"

#include <cmath>

#include "hinf/synth/controller_output.hpp"
#include "job_json.hpp"
#include "report_text.hpp"

namespace hinf::synth::controller_report {
namespace {

// The certificate's lines shared by verify and analyze.
std::string certificate_lines(const ControllerCertificate& c, bool discrete) {
  std::string out = std::string("closed loop stable    ") + (c.stable ? "yes" : "NO") + " (" +
                    (discrete ? "spectral radius " : "spectral abscissa ") + num(c.stability_margin_value) + ")\n";
  if (!c.stable) return out;
  out += "closed-loop Hinf norm " + num(c.closed_loop_hinf_norm) + " at " + num(c.peak_frequency) +
         (discrete ? " rad/sample" : " rad/s") + "\n";
  out += "largest pole modulus  " + num(c.max_pole_modulus) + (c.poles_in_disk ? "" : "  OUTSIDE the disk") + "\n";
  if (c.robust_channel_norm)
    out += "robust channel        ‖T_qp‖∞ = " + num(*c.robust_channel_norm) +
           (c.robustly_stable ? " < 1 (small gain: robustly stable)" : " >= 1  FAIL") + "\n";
  return out;
}

// The certificate section (controller_output.hpp) as JSON at `gamma`, without the LMI's
// eigenvalue and cond(N): those belong to a synthesised point, which verify and check do not have.
Json certificate_json(const ControllerCertificate& c, double gamma, bool discrete, bool disk) {
  Json j = job_json::from_yaml(controller_certificate_yaml(c, gamma, discrete, disk))["certificate"];
  for (const char* key : {"lmi_max_eigenvalue", "cond_N"}) j.erase(key);
  return j;
}

}  // namespace

std::string solve(const ControllerSynthesisResult& r, const ControllerConfig& cfg) {
  std::string out = "gamma = " + num(r.gamma) + " (the closed loop's Hinf norm, certified upper value); " +
                    (cfg.design.strictly_proper ? "strictly proper " : "") + to_string(cfg.plant.time) +
                    "-time controller [" + std::to_string(r.newton_iterations) + " Newton iterations, " +
                    num(r.time_s) + " s]\n" + "cond(N) = " + num(r.certificate.cond_N) +
                    "; gamma bounds the gain from w to z of the closed loop\n";
  if (r.stopped_short)
    out += "the solver stopped short of its gap tolerance (" + *r.stopped_short +
           "); the controller is that point's, certified\n";
  if (r.gamma_optimal && r.backoff > 0)  // (a narrower ball's optimum, without a back-off, is said below)
    out += std::string("gamma back-off") +
           (cfg.settings.gamma_backoff > 0 ? "" : " (automatic: I - R S is singular at the optimum)") +
           ": the LMI's optimum is " + num(*r.gamma_optimal) + "; the controller is recovered at (1 + " + num(r.backoff) +
           ") times it, at the point of largest LMI margin (docs/maths.md (149a))\n";
  if (r.narrower_ball)
    out += (r.wider_ball_certified_norm
                ? "the ball of the LMI's optimum " + num(*r.gamma_optimal_wider_ball) +
                      " certified a controller only at a large back-off (closed loop " + num(*r.wider_ball_certified_norm) + ")"
                : "no controller was certified from the ball of the LMI's optimum " + num(*r.gamma_optimal_wider_ball) +
                      " (at the optimum or any back-off)") +
           "; the LMI was solved again in the ball ||x|| < " + num(*r.narrower_ball) + ", whose optimum is " +
           num(*r.gamma_optimal) + ", and the controller recovered there (docs/maths.md §4.3)\n";
  if (r.gamma_without_disk && !r.robust_synthesis)
    out += "pole disk: without it the LMI's optimum is " + num(*r.gamma_without_disk) + " (+" +
           num(100 * (r.gamma / *r.gamma_without_disk - 1)) + " % for the disk)\n";
  if (r.robust_synthesis)
    out += "robust synthesis (docs/maths.md (160a)): the H-infinity-optimal controller had ‖T_qp‖∞ = " +
           num(*r.nominal_robust_channel_norm) + " >= 1; this one is designed for ‖T_qp‖∞ < 1 (D-scaling d = " +
           num(r.robust_scaling) + "; the least ‖T_qp‖∞ of any controller is about " +
           num(*r.least_robust_channel_norm) + ")\n";
  if (r.certificate.robust_channel_norm)
    out += "robust channel: ‖T_qp‖∞ = " + num(*r.certificate.robust_channel_norm) +
           " < 1: stable for every perturbation H F E with ‖F‖ <= 1 (small gain)\n";
  return out;
}

std::string analysis(const std::string& controller_path, std::optional<double> claimed_gamma,
                     const ControllerCertificate& c, bool discrete) {
  return "controller            " + controller_path +
         (claimed_gamma ? " (claims gamma " + num(*claimed_gamma) + ")" : "") + "\n" + certificate_lines(c, discrete);
}

std::string analysis_json(const std::string& config_path, const std::string& controller_path,
                          std::optional<double> claimed_gamma, const ControllerCertificate& c) {
  Json j = job_json::envelope("analyze", "controller", config_path);
  j["controller"] = controller_path;
  j["claimed_gamma"] = claimed_gamma ? json_num(*claimed_gamma) : Json(nullptr);
  j["closed_loop_stable"] = c.stable;
  j["stability_margin"] = json_num(c.stability_margin_value);
  j["closed_loop_hinf_norm"] = c.stable ? json_num(c.closed_loop_hinf_norm) : Json(nullptr);
  j["peak_frequency"] = c.stable ? json_num(c.peak_frequency) : Json(nullptr);
  j["max_pole_modulus"] = json_num(c.max_pole_modulus);
  j["robust_channel_hinf_norm"] = c.robust_channel_norm ? json_num(*c.robust_channel_norm) : Json(nullptr);
  return json_line(j);
}

std::string verification(double claimed_gamma, const ControllerVerification& v, bool discrete) {
  const ControllerCertificate& c = v.certificate;
  return "claimed gamma         " + num(claimed_gamma) + "\n" + certificate_lines(c, discrete) +
         (v.holds ? std::string("verified: the controller file's gamma holds\n")
                  : "NOT verified" + (c.stable ? ": the closed loop's norm is " + num(c.closed_loop_hinf_norm) + "\n"
                                               : std::string(": the closed loop is unstable\n")));
}

std::string check(double golden_gamma, const std::string& golden_sha256, const std::string& config_sha256,
                  double gamma_now, const ControllerGoldenComparison& cmp, double rtol) {
  std::string out = "gamma:      golden " + num(golden_gamma) + ", now " + num(gamma_now) + ", relative change " +
                    num(cmp.gamma_relative_change) + (cmp.same_gamma ? "  ok" : "  CHANGED") + "\n" + "controller: " +
                    (cmp.controller_difference
                         ? "||K_golden - K_now||_inf / ||K_golden||_inf = " + num(*cmp.controller_difference) +
                               " (transfer functions y -> u)"
                         : std::string("an unstable controller: no transfer-function norm")) +
                    (cmp.same_controller ? "  ok" : "  CHANGED") + "\n";
  if (cmp.golden_recertified)
    out += "            the golden controller on this config: closed-loop Hinf norm " +
           num(cmp.golden_recertified->closed_loop_hinf_norm) + " at the golden gamma" +
           (cmp.golden_recertified->passed ? ": an equally optimal controller (the optimum is not unique)\n"
                                           : ", certificate FAILED\n");
  if (!golden_sha256.empty() && golden_sha256 != config_sha256)
    out += "note: the golden file was generated from a config with another sha256 (" + golden_sha256.substr(0, 12) +
           "... vs " + config_sha256.substr(0, 12) + "...)\n";
  return out + (cmp.same() ? "same (rtol " + num(rtol) + ")\n" : "CHANGED (rtol " + num(rtol) + ")\n");
}

std::string verification_json(const std::string& config_path, const std::string& controller_path,
                              double claimed_gamma, const ControllerVerification& v, bool discrete, bool disk) {
  Json j = job_json::envelope("verify", "controller", config_path);
  j["controller"] = controller_path;
  j["claimed_gamma"] = json_num(claimed_gamma);
  j["holds"] = v.holds;
  j["certificate"] = certificate_json(v.certificate, claimed_gamma, discrete, disk);
  return json_line(j);
}

std::string check_json(const std::string& config_path, const std::string& golden_path, double golden_gamma,
                       const std::string& golden_sha256, const std::string& config_sha256, double gamma_now,
                       const ControllerGoldenComparison& cmp, double rtol, bool discrete, bool disk) {
  Json j = job_json::envelope("check", "controller", config_path);
  j["golden"] = golden_path;
  j["rtol"] = json_num(rtol);
  j["same"] = cmp.same();
  j["gamma_golden"] = json_num(golden_gamma);
  j["gamma_now"] = json_num(gamma_now);
  j["gamma_relative_change"] = json_num(cmp.gamma_relative_change);
  j["same_gamma"] = cmp.same_gamma;
  j["transfer_function_difference"] = cmp.controller_difference ? json_num(*cmp.controller_difference) : Json(nullptr);
  j["same_design"] = cmp.same_controller;
  j["golden_recertified"] =
      cmp.golden_recertified ? certificate_json(*cmp.golden_recertified, golden_gamma, discrete, disk) : Json(nullptr);
  j["golden_config_sha256"] = golden_sha256.empty() ? Json(nullptr) : Json(golden_sha256);
  j["config_sha256"] = config_sha256;
  return json_line(j);
}

std::string discretised(const std::string& controller_path, double period, ControllerSampling method,
                        std::optional<double> continuous_gamma, bool holds, const ControllerCertificate& c) {
  std::string out = "controller            " + controller_path +
                    (continuous_gamma ? " (continuous loop: gamma " + num(*continuous_gamma) + ")" : "") + "\n" +
                    "discretised           " + (method == ControllerSampling::Tustin ? "Tustin's rule" : "zero-order hold") +
                    " at T = " + num(period) + " s; the plant sampled at T, w and u held (docs/maths.md (161b))\n" +
                    certificate_lines(c, true);
  if (holds)
    return out + "certified: the sampled loop's l2 gain from w to z is at most " + num(c.closed_loop_hinf_norm) + "\n";
  return out + "NOT certified: the sampled loop " +
         (!c.stable ? std::string("is unstable (spectral radius ") + num(c.stability_margin_value) + " >= 1)"
                    : !c.robustly_stable ? "fails the robust channel's small-gain test (‖T_qp‖∞ = " +
                                               num(*c.robust_channel_norm) + " >= 1)"
                                         : std::string("has no finite certified norm")) +
         "; sample faster or design for the discrete plant (time: discrete)\n";
}

std::string discretised_json(const std::string& config_path, const std::string& controller_path, double period,
                             ControllerSampling method, std::optional<double> continuous_gamma, bool holds,
                             const ControllerCertificate& c) {
  Json j = job_json::envelope("discretise", "controller", config_path);
  j["controller"] = controller_path;
  j["method"] = to_string(method);
  j["sample_time"] = json_num(period);
  j["continuous_gamma"] = continuous_gamma ? json_num(*continuous_gamma) : Json(nullptr);
  j["holds"] = holds;
  j["gamma"] = holds ? json_num(c.closed_loop_hinf_norm) : Json(nullptr);
  j["certificate"] = certificate_json(c, holds ? c.closed_loop_hinf_norm : INFINITY, true, false);
  return json_line(j);
}

}  // namespace hinf::synth::controller_report
