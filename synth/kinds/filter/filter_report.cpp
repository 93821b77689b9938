// The filter kind's reports (filter_report.hpp).
#include "filter_report.hpp"

#include <cmath>
#include <cstdio>

#include "hinf/sdp/time_model.hpp"
#include "hinf/synth/gains_output.hpp"
#include "job_json.hpp"
#include "report_text.hpp"

namespace hinf::synth::filter_report {
namespace {

constexpr double kPi = 3.14159265358979323846;

// printf into a string (the verbose lines keep the table layout they always had).
template <class... Args>
std::string format(const char* fmt, Args... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

// θ rad/sample at sample time T is θ/(2πT) Hz.
double peak_hz(const FilterAnalysis& a, double T) { return a.hinf_norm_peak_frequency / (2 * kPi * T); }

// "(A_F, B_F, C_F, G_F = A - K C, K, L, G to 1e-16)" or "(NOT A - K C, K, L, G: relative
// difference ...)" above 1e-12; for a filtered estimate with C_F, D_F = L - L M C, L M (docs/maths.md (140)).
std::string observer_realisation_text(const Filter& f, double mismatch) {
  const std::string names = f.filtered() ? "A_F, B_F, C_F, D_F, G_F" : "A_F, B_F, C_F, G_F";
  const std::string values = f.filtered() ? "A - K C, K, L - L M C, L M, G" : "A - K C, K, L, G";
  return mismatch <= 1e-12 ? " (" + names + " = " + values + " to " + num(mismatch) + ")"
                           : " (NOT " + values + ": relative difference " + num(mismatch) + ")";
}

// "multiplier λ", or with F block-diagonal "multipliers [λ₁, λ₂] (one per block of F)".
std::string multipliers_text(const Certificate& c) {
  if (c.robust_block_multipliers.size() == 0) return "multiplier " + num(c.robust_multiplier);
  std::string out = "multipliers [";
  for (Eigen::Index b = 0; b < c.robust_block_multipliers.size(); ++b)
    out += (b ? ", " : "") + num(c.robust_block_multipliers(b));
  return out + "] (one per block of F)";
}

// When the solver stopped short of its gap tolerance: what the written filter is.
std::string stopped_short_line(const SolverInfo& s) {
  if (s.status != sdp::Status::StoppedShort) return "";
  return "the solver stopped short of its gap tolerance (" +
         (s.gap_certified ? "certified relative gap " + num(s.relative_gap) : "gap not certified: " + s.gap_detail) +
         "); the filter is the last centred point's, certified\n";
}


// The certificate section (gains_output.hpp) as JSON, without check 1 and the recovery's
// conditioning: those belong to a synthesised point, which verify and check do not have.
Json certificate_json(const Certificate& c, FilterForm form) {
  Json j = job_json::from_yaml(certificate_yaml(c, form))["certificate"];
  for (const char* key : {"lmi_negative_definite", "lmi_max_eigenvalue", "lmi_max_eigenvalue_relative", "cond_S",
                          "cond_R_minus_S", "cond_P"})
    j.erase(key);
  return j;
}

}  // namespace

void log_before_solve(const Plant& p, const Settings& settings, const LogLine& log) {
  const auto range = [&](const char* name, const Eigen::MatrixXd& M) {
    double lo = INFINITY, hi = 0;
    for (Eigen::Index i = 0; i < M.size(); ++i) {
      const double a = std::abs(M.data()[i]);
      if (a > 0) lo = std::min(lo, a), hi = std::max(hi, a);
    }
    log(hi == 0 ? format("  %-2s %dx%d  all zero", name, (int)M.rows(), (int)M.cols())
                : format("  %-2s %dx%d  |nonzero| in [%.3g, %.3g]", name, (int)M.rows(), (int)M.cols(), lo, hi));
  };
  log("plant coefficient ranges:");
  range("A", p.A);
  range("B", p.B);
  range("C", p.C);
  range("D", p.D);
  range("L", p.L);
  if (p.uncertain()) {
    range("H", p.H);
    range("E", p.E);
  }
  const ProblemSize size = problem_size(p, settings);
  log(format("%s form: LMI order %d, %d variables; solver memory estimate %.0f MiB (limit max_memory_mb = %.0f)",
             to_string(size.form), size.lmi_order, size.variables, std::ceil(size.memory_mib),
             settings.max_memory_mb));
  log(format("time estimate (docs/benchmarks.md \"Time\"): %s per Newton iteration, %s to %s for %d-%d of them, "
             "on a machine like the development one",
             duration_text(size.newton_iteration_s).c_str(), duration_text(size.fewest_s).c_str(),
             duration_text(size.most_s).c_str(), sdp::kFewestNewtonIterations, sdp::kMostNewtonIterations));
}

void log_after_solve(const SolverInfo& s, const LogLine& log) {
  log(format("LMI order %d, %d variables; scaling applied (powers of two, exact): %s", s.lmi_order, s.variables,
             s.scaling.c_str()));
  log(s.gap_certified ? format("optimality gap certified by a dual point: gamma*^2 in [%.10g, %.10g]",
                               s.dual_bound_gamma_squared, s.optimal_gamma * s.optimal_gamma)
                      : "optimality gap not certified: " + s.gap_detail);
}

std::string solve(const SynthesisResult& r) {
  return "gamma = " + num(r.gamma) + " (nominal Hinf norm " + num(r.certificate.hinf_norm_nominal) +
         ", robust bound " + num(r.certificate.robust_bound) + "), certified [" +
         std::to_string(r.solver.newton_iterations) + " Newton iterations, " + num(r.solver.time_s) + " s]\n" +
         "RMS error under unit white noise (H2 norm) " + num(r.certificate.h2_norm_nominal) +
         " (compare: hinf-synth kalman)\n" + stopped_short_line(r.solver) + "filter form: " + to_string(r.filter.form) +
         (r.filter.filtered() ? ", filtered estimate" : "") + "; " + r.bound + "\n" +
         (r.augmented_infeasible.empty()
              ? std::string()
              : "filter.form: auto chose the observer form: Theorem 1's augmented filter is infeasible here (" +
                    r.augmented_infeasible + ")\n");
}

std::string kalman(const SynthesisResult& r) {
  return std::string(r.filter.filtered() ? "Kalman filter x_hat(k|k)" : "Kalman predictor") +
         ": worst-case gain gamma = " + num(r.gamma) + " (certified; nominal Hinf norm " +
         num(r.certificate.hinf_norm_nominal) + "), RMS error under unit white noise (H2 norm) " +
         num(r.certificate.h2_norm_nominal) + "\n";
}

std::string analysis(const std::string& gains_path, const runtime_yaml::GainsFile& g, const FilterAnalysis& a,
                     std::optional<double> T, bool uncertain) {
  std::string out =
      "gains                      " + gains_path + (g.gamma ? " (claims gamma " + num(*g.gamma) + ")" : "") + "\n" +
      "spectral radius (nominal)  " + num(a.spectral_radius_nominal) + "\n" +
      "nominal Hinf norm          " + num(a.hinf_norm_nominal) + " at " + num(a.hinf_norm_peak_frequency) +
      " rad/sample" + (T ? " = " + num(peak_hz(a, *T)) + " Hz (T = " + num(*T) + " s)" : "") + "\n" +
      "sampled spectral radius    " + num(a.spectral_radius_sampled_max) + " (max over admissible F)\n" +
      "robust bound (LMI)         " + num(a.robust_bound) +
      (uncertain ? "" : " (no uncertainty: the nominal norm, LMI (50)'s infimum)") + "\n";
  if (a.has_worst_F)
    out += "worst case found           " + num(a.worst_F_gain) + " at a constant admissible F (" +
           std::to_string(a.worst_F_evaluations) + " norms; sampled, then a local search): the worst-case gain lies in [" +
           num(a.worst_F_gain) + ", " + num(a.robust_bound) + "]\n";
  if (!a.worst_parameters.empty()) {
    std::string at;
    for (const auto& p : a.worst_parameters) at += (at.empty() ? "" : ", ") + p.name + " = " + num(p.value);
    out += "worst case in the box      " + num(a.worst_parameters_gain) + " at " + at + " (" +
           std::to_string(a.worst_parameters_evaluations) + " norms over the parameters' ranges, design model)\n";
  }
  if (!a.delta_grid.empty())
    out += "worst case on delta grid   " + num(a.worst_delta_hinf_norm) + " at delta = " + num(a.worst_delta) + " (" +
           std::to_string(a.delta_grid.size()) + " points, exact plant)\n";
  return out;
}

std::string analysis_json(const std::string& config_path, const std::string& gains_path,
                          const runtime_yaml::GainsFile& g, const FilterAnalysis& a, std::optional<double> T) {
  Json j = job_json::envelope("analyze", "filter", config_path);
  j["gains"] = gains_path;
  j["claimed_gamma"] = g.gamma ? json_num(*g.gamma) : Json(nullptr);
  j["spectral_radius_nominal"] = json_num(a.spectral_radius_nominal);
  j["hinf_norm_nominal"] = json_num(a.hinf_norm_nominal);
  j["hinf_norm_peak_frequency"] = json_num(a.hinf_norm_peak_frequency);
  j["sample_time_s"] = T ? json_num(*T) : Json(nullptr);
  j["hinf_norm_peak_frequency_hz"] = T ? json_num(peak_hz(a, *T)) : Json(nullptr);
  j["spectral_radius_sampled_max"] = json_num(a.spectral_radius_sampled_max);
  j["robust_bound"] = json_num(a.robust_bound);
  if (a.has_worst_F) {
    j["worst_F_gain"] = json_num(a.worst_F_gain);
    Json rows = Json::array();
    for (Eigen::Index r = 0; r < a.worst_F.rows(); ++r) {
      Json row = Json::array();
      for (Eigen::Index c = 0; c < a.worst_F.cols(); ++c) row.push_back(json_num(a.worst_F(r, c)));
      rows.push_back(std::move(row));
    }
    j["worst_F"] = std::move(rows);
    j["worst_F_evaluations"] = a.worst_F_evaluations;
  }
  if (!a.worst_parameters.empty()) {
    Json values = Json::object();
    for (const auto& p : a.worst_parameters) values[p.name] = json_num(p.value);
    j["worst_parameters"] = std::move(values);
    j["worst_parameters_gain"] = json_num(a.worst_parameters_gain);
    j["worst_parameters_evaluations"] = a.worst_parameters_evaluations;
  }
  if (!a.delta_grid.empty()) {
    j["worst_delta"] = json_num(a.worst_delta);
    j["worst_delta_hinf_norm"] = json_num(a.worst_delta_hinf_norm);
    Json grid = Json::array();
    for (const auto& p : a.delta_grid) {
      Json point = Json::object();
      point["delta"] = json_num(p.delta);
      point["spectral_radius"] = json_num(p.spectral_radius);
      point["hinf_norm"] = json_num(p.hinf_norm);
      grid.push_back(std::move(point));
    }
    j["delta_grid"] = std::move(grid);
  }
  return json_line(j);
}

std::string verification(const Filter& f, double claimed_gamma, const Verification& v) {
  const Certificate& c = v.certificate;
  std::string out = "claimed gamma         " + num(claimed_gamma) + "\n" + "filter form           " +
                    to_string(f.form) + (f.filtered() ? ", filtered estimate" : "") +
                    (f.form == FilterForm::Observer ? observer_realisation_text(f, c.observer_mismatch) : std::string()) +
                    "\n" + "schur stable          " + (c.schur_stable ? "yes" : "NO") + " (spectral radius nominal " +
                    num(c.spectral_radius_nominal) + ", sampled max " + num(c.spectral_radius_sampled_max) + " over " +
                    std::to_string(c.stability_samples) + " F)\n";
  if (c.schur_stable)
    out += "nominal Hinf norm     " + num(c.hinf_norm_nominal) + (c.hinf_norm_ok ? " <= gamma" : " > gamma  FAIL") + "\n" +
           "robust analysis LMI   " +
           (c.robust_feasible_at_gamma ? "feasible at gamma (S-procedure " + multipliers_text(c) + ", scaled norm " +
                                             num(c.robust_scaled_norm) + " < 1; feasible down to " + num(c.robust_bound) + ")"
                                       : "infeasible at gamma (best scaled norm " + num(c.robust_scaled_norm) + " >= 1)  FAIL") +
           "\n";
  const std::string achieved = !c.schur_stable   ? std::string("none (unstable)")
                               : v.achieved_bound ? num(*v.achieved_bound)
                                                  : "unknown (" + v.achieved_unknown_reason + ")";
  return out + (v.holds ? std::string("verified: the gains file's gamma holds\n")
                        : "NOT verified: the bound actually achieved is " + achieved + "\n");
}

std::string check(const runtime_yaml::GainsFile& g, const std::string& config_sha256, double gamma_now,
                  const GoldenComparison& cmp, double rtol) {
  std::string why;
  if (cmp.golden_recertified) {
    const Certificate& c = *cmp.golden_recertified;
    why = "        the golden filter on this config: nominal Hinf norm " + num(c.hinf_norm_nominal) +
          ", robust analysis LMI " +
          (c.robust_feasible_at_gamma ? "feasible" : "infeasible (best scaled norm " + num(c.robust_scaled_norm) + ")") +
          " at the golden gamma" + (cmp.same_filter ? ": an equally optimal filter (the optimum is not unique)\n" : "\n");
  }
  std::string out = "gamma:  golden " + num(*g.gamma) + ", now " + num(gamma_now) + ", relative change " +
                    num(cmp.gamma_relative_change) + (cmp.same_gamma ? "  ok" : "  CHANGED") + "\n" +
                    "filter: ||F_golden - F_now||_inf / ||F_golden||_inf = " + num(cmp.filter_difference.relative) +
                    " (transfer functions y -> z_F)" + (cmp.same_filter ? "  ok" : "  CHANGED") + "\n" + why;
  if (!g.config_sha256.empty() && g.config_sha256 != config_sha256)
    out += "note: the golden file was generated from a config with another sha256 (" + g.config_sha256.substr(0, 12) +
           "... vs " + config_sha256.substr(0, 12) + "...)\n";
  return out + (cmp.same() ? "same (rtol " + num(rtol) + ")\n" : "CHANGED (rtol " + num(rtol) + ")\n");
}

std::string verification_json(const std::string& config_path, const std::string& gains_path, const Filter& f,
                              double claimed_gamma, const Verification& v) {
  Json j = job_json::envelope("verify", "filter", config_path);
  j["gains"] = gains_path;
  j["claimed_gamma"] = json_num(claimed_gamma);
  j["holds"] = v.holds;
  j["achieved_bound"] = v.achieved_bound ? json_num(*v.achieved_bound) : Json(nullptr);
  j["achieved_unknown_reason"] = v.achieved_unknown_reason.empty() ? Json(nullptr) : Json(v.achieved_unknown_reason);
  j["certificate"] = certificate_json(v.certificate, f.form);
  return json_line(j);
}

std::string check_json(const std::string& config_path, const std::string& golden_path, const runtime_yaml::GainsFile& g,
                       const Filter& golden_filter, const std::string& config_sha256, double gamma_now,
                       const GoldenComparison& cmp, double rtol) {
  Json j = job_json::envelope("check", "filter", config_path);
  j["golden"] = golden_path;
  j["rtol"] = json_num(rtol);
  j["same"] = cmp.same();
  j["gamma_golden"] = json_num(*g.gamma);
  j["gamma_now"] = json_num(gamma_now);
  j["gamma_relative_change"] = json_num(cmp.gamma_relative_change);
  j["same_gamma"] = cmp.same_gamma;
  j["transfer_function_difference"] = json_num(cmp.filter_difference.relative);
  j["same_design"] = cmp.same_filter;
  j["golden_recertified"] =
      cmp.golden_recertified ? certificate_json(*cmp.golden_recertified, golden_filter.form) : Json(nullptr);
  j["golden_config_sha256"] = g.config_sha256.empty() ? Json(nullptr) : Json(g.config_sha256);
  j["config_sha256"] = config_sha256;
  return json_line(j);
}

}  // namespace hinf::synth::filter_report
