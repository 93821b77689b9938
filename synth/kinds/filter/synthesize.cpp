// The synthesis pipeline (docs/maths.md §2.5–§7): pre-flight checks, Theorem 1 /
// Corollary 1 by the barrier method, recovery (22), and the independent certificate.
#include <cmath>

#include "hinf/common/number_text.hpp"
#include "hinf/synth/validate_plant.hpp"
#include "hinf/sdp/path_following.hpp"
#include "hinf/lmi/sdpa_format.hpp"
#include "hinf/certify/dense_lmi.hpp"
#include "hinf/certify/scaled_bounded_real.hpp"
#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/stability.hpp"
#include "hinf/certify/quadratic_stability.hpp"
#include "hinf/synth/plant_scaling.hpp"
#include "hinf/synth/synthesis.hpp"
#include "hinf/sdp/dual_bound.hpp"
#include "pipeline.hpp"
#include "observer_lmi.hpp"
#include "theorem1.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// A necessary condition's value above which a numerical failure is reported as "near the
// boundary of feasibility".
constexpr double kNearBoundaryGain = 0.9;

// Pre-flight (docs/maths.md [D10]): the error system contains the plant state, so the plant
// must be Schur stable for every admissible F (docs/maths.md §2.5). Name the offending mode.
// The plant is the scaled one; its eigenvalues are computed balanced (docs/maths.md §4.4).
// Returns ‖E (zI − A)⁻¹ H‖∞ (NaN without uncertainty): how close the plant is to the
// boundary of feasibility (119), for the message of a solve that fails near it.
double preflight(const Plant& plant, const Settings& settings) {
  // γ* = 0 (docs/maths.md §2.4): without process noise the state stays at 0, without an
  // estimated output there is nothing to estimate — the zero filter is exact, and Theorem 1
  // has no strictly feasible point with g > 0 that the solver could approach.
  if (plant.B.isZero(0.0))
    throw Error(ErrorCode::Infeasible,
                "ill-posed: the process-noise matrix B is zero, so the state is never excited and the optimal bound is γ* = 0 "
                "(the zero filter is exact); nothing to synthesise");
  if (plant.L.isZero(0.0))
    throw Error(ErrorCode::Infeasible,
                "ill-posed: the estimated-output matrix L is zero, so there is no output to estimate and γ* = 0; nothing to synthesise");
  const std::complex<double> worst = certify::dominant_eigenvalue(plant.A);
  const double rho = std::abs(worst);
  if (!(rho < 1.0)) {
    throw Error(ErrorCode::Infeasible,
                "plant is not Schur stable: spectral radius of A is " + fmt(rho) + " (eigenvalue " +
                    fmt(worst.real()) + (worst.imag() >= 0 ? " + " : " - ") + fmt(std::abs(worst.imag())) +
                    "i); the augmented filter of Theorem 1 (filter.form: augmented) has the plant state in its error "
                    "system, so no such filter is stable (docs/maths.md §2.5); the observer form (filter.form: observer, "
                    "or auto) needs (A, C) detectable only (docs/maths.md §18)");
  }
  if (plant.uncertain()) {
    // The zero filter's error system has the plant's A + HFE as its top-left block.
    Filter zero;
    zero.A_F = MatrixXd::Zero(plant.n(), plant.n());
    zero.B_F = MatrixXd::Zero(plant.n(), plant.m());
    zero.C_F = MatrixXd::Zero(plant.l(), plant.n());
    const certify::StabilitySample s =
        certify::sampled_robust_stability(plant, zero, settings.stability_samples, settings.seed);
    if (!(s.max_spectral_radius < 1.0)) {
      throw Error(ErrorCode::Infeasible,
                  "plant is not robustly Schur stable: for an admissible F (‖F‖ ≤ 1) the spectral "
                  "radius of A + H F E is " + fmt(s.max_spectral_radius) +
                  " (nominal " + fmt(rho) + "), so the augmented formulation (its error contains x) has no finite ℓ₂ gain "
                  "for this uncertainty (docs/maths.md §2.5); reduce the uncertainty (H, E), or design in observer form "
                  "(filter.form: observer), where the uncertainty acts on the error dynamics (docs/maths.md (122))");
    }
    // Robust stability is not enough: Theorem 1 needs a quadratic Lyapunov function for
    // every admissible F, i.e. ‖E (zI − A)⁻¹ H‖∞ < 1 (docs/maths.md §3.7, eq. (119)). For a
    // block-diagonal F the witness's full F₀ is not admissible: no such verdict (§23).
    if (plant.structured()) return NAN;
    const certify::GainWitness w = certify::uncertainty_gain_witness(plant.A, plant.H, plant.E);
    if (w.verified)
      throw Error(ErrorCode::Infeasible,
                  "infeasible, with a certificate: A + H F E is robustly Schur stable for the sampled F but not "
                  "quadratically stable — the uncertainty channel's gain ‖E (zI − A)⁻¹ H‖ is at least " +
                      fmt(w.gain_lower_bound) + " > 1 at θ = " + fmt(w.theta) +
                      " rad/sample (verified), so no Lyapunov matrix serves every admissible F and Theorem 1 has no "
                      "solution for any γ (docs/maths.md (119)); H∞ norm of that channel " + fmt(w.gain) +
                      " (scaling H or E by less than 1/" + fmt(w.gain) + " meets this necessary condition)");
    return w.gain;
  }
  return NAN;
}

// What to add to a numerical failure near the boundary of feasibility (docs/maths.md (119)).
std::string boundary_hint(double uncertainty_gain) {
  if (!(uncertainty_gain > kNearBoundaryGain)) return "";
  return "; the uncertainty channel's gain ‖E (zI − A)⁻¹ H‖∞ = " + fmt(uncertainty_gain) +
         " is close to 1, the boundary beyond which no filter exists (docs/maths.md (119)): near it the feasible "
         "set is thin and γ* large, likely beyond this solver's accuracy — reduce the uncertainty (H, E)";
}




// The robust analysis LMI docs/maths.md (50) (Lemma 1 with the S-procedure) for a fixed filter,
// minimising γ² by the barrier method (`analyze`; the certificate uses the bounded-real
// form of the same LMI instead, certify/scaled_bounded_real.hpp). Returns γ².
double solve_analysis(const Plant& user_plant, const Filter& user, const Settings& settings) {
  const PlantScaling sc = choose_scaling(user_plant);
  const AnalysisLmi A = build_analysis_lmi(scaled_plant(user_plant, sc), scaled_filter(user, sc));
  require_memory(A.lmi, settings, "the robust analysis LMI");
  const VectorXd c = A.lmi.cost_of(A.g);
  const sdp::Solution sol = sdp::minimize_linear(A.lmi, c, settings.solver);
  if (!sdp::has_point(sol.status))
    throw Error(error_code_for(sol.status), "robust analysis LMI (docs/maths.md (50)): " +
                                                std::string(sdp::status_message(sol.status)) +
                                                (sol.detail.empty() ? "" : ": " + sol.detail));
  return sol.objective / (sc.gamma_factor() * sc.gamma_factor());
}

// Without uncertainty the analysis LMI (50) is the bounded-real lemma, whose infimum over γ
// is the error system's H∞ norm: the symplectic pencil gives it, certified to
// kNominalBoundTolerance, with no SDP — whose optimum is then an unattained point of the
// boundary, where the barrier method can fail on round-off (a nilpotent plant's did).
constexpr double kNominalBoundTolerance = 1e-10;
double nominal_bound(const Plant& plant, const Filter& filter) {
  const StateSpace es = certify::error_system(plant, filter);
  const double rho = certify::spectral_radius(es.A);
  if (!(rho < 1))
    throw Error(ErrorCode::Infeasible, "the error system is not Schur stable (spectral radius " + fmt(rho) +
                                           "): no finite bound (docs/maths.md (50))");
  return certify::discrete_hinf_norm(es, kNominalBoundTolerance).norm;
}

}  // namespace

double robust_bound(const Plant& plant, const Filter& filter, const Settings& settings) {
  validate_plant(plant);
  settings.validate();
  if (!plant.uncertain()) return nominal_bound(plant, filter);
  return std::sqrt(solve_analysis(plant, filter, settings));
}


Certificate certify_filter(const Plant& plant, const Filter& filter, double gamma,
                           const Settings& settings) {
  validate_plant(plant);
  settings.validate();
  const PlantScaling sc = choose_scaling(plant);
  const Certificate c = certify_checks(scaled_plant(plant, sc), scaled_filter(filter, sc), gamma * sc.gamma_factor(), settings);
  return in_user_units(c, sc, filter);
}

namespace {



// Checks 1–4 of the certificate at Theorem 1's point, and the recovery's conditioning.
void certify_result(const Plant& plant, const certify::Theorem1Point& pt, const Settings& settings,
                    SynthesisResult& res) {
  certify_at_point(plant, certify::theorem1_matrix(plant, pt), pt.g, settings, pt.lambda, res);
  Certificate& cert = res.certificate;
  const VectorXd eig_S = Eigen::SelfAdjointEigenSolver<MatrixXd>(pt.S, Eigen::EigenvaluesOnly).eigenvalues();
  const VectorXd eig_RS =
      Eigen::SelfAdjointEigenSolver<MatrixXd>(pt.R - pt.S, Eigen::EigenvaluesOnly).eigenvalues();
  cert.cond_S = eig_S(eig_S.size() - 1) / eig_S(0);
  cert.cond_R_minus_S = eig_RS(0) > 0 ? eig_RS(eig_RS.size() - 1) / eig_RS(0) : INFINITY;
}

// Theorem 1 / Corollary 1 on the scaled plant (docs/maths.md §3).
SynthesisResult synthesize_augmented(const Plant& plant, const PlantScaling& sc, const Settings& settings,
                                     const IterationObserver& observer) {
  const double uncertainty_gain = preflight(plant, settings);
  const Theorem1Lmi T = build_theorem1(plant);
  const std::vector<lmi::SparseEntry> basis_error = theorem1_basis_error(T, plant);
  // Corollary 1, docs/maths.md (21): minimise γ² subject to LMI (18)
  const sdp::Solution sol = solve_min_gamma(T.lmi, T.g, basis_error, settings, observer, "Theorem 1 LMI",
                                            plant.structured()
                                                ? structured_infeasible_hint()
                                                : " (the plant is robustly Schur stable for the sampled F, but the "
                                                  "uncertainty bound H, E is too large for a quadratic certificate)",
                                            boundary_hint(uncertainty_gain));
  SynthesisResult res;
  res.solver = solver_info(sol, T.lmi, sc, settings);
  record_bracket(T.lmi, T.g, basis_error, sol, settings, sc.gamma_factor(), res.solver);

  const auto backoff = solve_gamma_backoff<Theorem1Lmi>(
      sol, [&](double g2) { return build_theorem1_backoff(plant, g2); }, settings, observer, res.solver);
  const certify::Theorem1Point pt =
      backoff ? theorem1_point(backoff->problem, plant, backoff->solution.x, backoff->gamma_squared)
              : theorem1_point(T, plant, sol.x, sol.objective);
  res.filter = recover_filter(pt);
  certify_result(plant, pt, settings, res);
  return res;
}

// filter.form: auto on a Schur-stable plant (docs/maths.md §18.4): Theorem 1's augmented filter,
// and — when it is infeasible (its verdict: not robustly stable, no quadratic certificate, or
// the LMI verified infeasible) — the observer form, whose uncertainty acts on the error
// dynamics (122) and which may exist where the augmented one does not. Infeasible in both:
// exit 3 with both verdicts; the observer form failing otherwise: its error, the augmented
// verdict beside it (a certificate about one form only is not one about `auto`).
SynthesisResult synthesize_augmented_or_observer(const Plant& plant, const PlantScaling& sc, const Settings& settings,
                                                 const IterationObserver& observer) {
  try {
    return synthesize_augmented(plant, sc, settings, observer);
  } catch (const Error& augmented) {
    if (augmented.code() != ErrorCode::Infeasible) throw;
    try {
      SynthesisResult res = synthesize_observer(plant, sc, settings, observer);
      res.augmented_infeasible = augmented.what();
      return res;
    } catch (const Error& obs) {
      throw Error(obs.code(),
                  std::string(obs.code() == ErrorCode::Infeasible ? "infeasible in both forms of filter.form: auto: "
                                                                  : "filter.form: auto: ") +
                      "Theorem 1's augmented filter: " + augmented.what() + "; the observer form (docs/maths.md §18): " +
                      obs.what(),
                  obs.key().empty() ? augmented.key() : obs.key());
    }
  }
}

// The formulation to solve first (docs/maths.md §18.4): Auto is Theorem 1's augmented filter
// for a Schur-stable plant without a known input (the paper's problem) and the predicted
// estimate — with the observer form after it if it is infeasible — the observer form otherwise.
FilterForm resolve_form(const Plant& plant, const Settings& settings) {
  if (settings.form == FormChoice::Augmented) return FilterForm::Augmented;
  if (settings.form == FormChoice::Observer || plant.r() > 0 || settings.estimate == Estimate::Filtered)
    return FilterForm::Observer;
  return certify::spectral_radius(plant.A) < 1.0 ? FilterForm::Augmented : FilterForm::Observer;
}

}  // namespace


// Every step runs on the scaled plant (docs/maths.md §4.4), an exact change of units; the
// filter and every reported number are mapped back to the user's units at the end.
SynthesisResult synthesize(const Plant& user_plant, const Settings& settings, const IterationObserver& observer) {
  validate_plant(user_plant);
  settings.validate();
  const PlantScaling sc = choose_scaling(user_plant);
  const Plant plant = scaled_plant(user_plant, sc);
  const FilterForm form = resolve_form(plant, settings);
  SynthesisResult res = form == FilterForm::Observer ? synthesize_observer(plant, sc, settings, observer)
                        : settings.form == FormChoice::Auto ? synthesize_augmented_or_observer(plant, sc, settings, observer)
                                                            : synthesize_augmented(plant, sc, settings, observer);
  if (!res.certificate.passed)
    throw Error(ErrorCode::NumericalFailure,
                "certificate failed, no filter written:" + failed_checks(res.certificate, res.gamma));
  const double f = sc.gamma_factor();
  res.bound = bound_statement(res.filter.form, user_plant.uncertain(), settings.estimate);
  if (user_plant.structured())
    res.bound += "; F = diag(F_1, " + std::string(user_plant.F_blocks.size() > 2 ? "..., " : "") + "F_" +
                 std::to_string(user_plant.F_blocks.size()) +
                 "), each ||F_b(k)|| <= 1, one S-procedure multiplier per block (docs/maths.md §23)";
  res.filter = user_filter(res.filter, sc);
  res.certificate = in_user_units(res.certificate, sc, res.filter);
  res.gamma /= f;
  res.gamma_squared /= f * f;
  return res;
}

std::string bound_statement(FilterForm form, bool uncertain, Estimate estimate) {
  if (form == FilterForm::Observer && estimate == Estimate::Filtered)
    return std::string("gamma bounds the l2 gain from (w, v) to z - z_hat(k|k) = (L - L M C) e - L M D v, the filtered ") +
           "estimate z_hat(k|k) = L x_hat(k|k), x_hat(k|k) = x_hat + M (y - C x_hat), e = x - x_hat, for e(k+1) = (A" +
           (uncertain ? " + H F E" : "") + " - K C) e + B w - K D v" +
           (uncertain ? " and every ||F(k)|| <= 1: the uncertainty acting on the error dynamics; the plant's own H F E x "
                        "term, unseen by the filter, is not covered"
                      : "; the known input u cancels exactly") +
           " (docs/maths.md (141))";
  if (form == FilterForm::Augmented)
    return uncertain ? "gamma bounds the l2 gain from (w, v) to e = z - z_F for every admissible F(k), ||F(k)|| <= 1, "
                       "of the plant's A + H F E (docs/maths.md (13))"
                     : "gamma bounds the l2 gain from (w, v) to e = z - z_F (the H-infinity norm of the error system, "
                       "docs/maths.md (12))";
  return uncertain ? "gamma bounds the l2 gain from (w, v) to z - z_hat = L e, e = x - x_hat, for e(k+1) = (A + H F E - K C) e "
                     "+ B w - K D v and every ||F(k)|| <= 1: the uncertainty acting on the error dynamics; the plant's "
                     "own H F E x term, unseen by the filter, is not covered (docs/maths.md (122)-(123))"
                   : "gamma bounds the l2 gain from (w, v) to z - z_hat = L e, e = x - x_hat, e(k+1) = (A - K C) e + B w - K D v; "
                     "the known input u cancels exactly (docs/maths.md (122)-(123))";
}

SynthesisResult synthesize(const Plant& plant, const Settings& settings) {
  return synthesize(plant, settings, nullptr);
}

std::string theorem1_sdpa(const Plant& plant, const std::string& comment) {
  validate_plant(plant);
  // the user's own problem (γ² is the objective), with only the H/E split of (24)
  const PlantScaling sc = uncertainty_split(plant);
  const Theorem1Lmi T = build_theorem1(scaled_plant(plant, sc));
  const VectorXd c = T.lmi.cost_of(T.g);
  return lmi::to_sdpa_sparse(T.lmi, c, comment + "\nvariable " + std::to_string(T.lmi.variable(T.g).offset + 1) +
                                           " is gamma^2; " + sc.summary());
}

ProblemSize problem_size(const Plant& user_plant, const Settings& settings) {
  validate_plant(user_plant);
  const Plant plant = scaled_plant(user_plant, choose_scaling(user_plant));
  ProblemSize size;
  size.form = resolve_form(plant, settings);
  const lmi::LmiProblem lmi =
      size.form == FilterForm::Observer ? build_observer_lmi(plant, settings.estimate).lmi : build_theorem1(plant).lmi;
  size.lmi_order = lmi.order();
  size.variables = lmi.num_params();
  size.memory_mib = estimated_solve_mib(lmi);
  const sdp::TimeEstimate time = estimated_solve_time(lmi);
  size.newton_iteration_s = time.newton_iteration_s;
  size.fewest_s = time.fewest_s;
  size.most_s = time.most_s;
  return size;
}

std::string synthesis_sdpa(const Plant& plant, const Settings& settings, const std::string& comment) {
  validate_plant(plant);
  if (resolve_form(plant, settings) == FilterForm::Augmented)
    return theorem1_sdpa(plant, "Theorem-1 LMI (18) " + comment);
  const PlantScaling sc = uncertainty_split(plant);
  const ObserverLmi O = build_observer_lmi(scaled_plant(plant, sc), settings.estimate);
  return lmi::to_sdpa_sparse(O.lmi, O.lmi.cost_of(O.g),
                             std::string(O.N ? "filtered observer-form LMI (142) " : "observer-form LMI (124) ") + comment + "\nvariable " +
                                 std::to_string(O.lmi.variable(O.g).offset + 1) + " is gamma^2; " + sc.summary());
}

}  // namespace hinf::synth
