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
#include "hinf/sdp/memory_model.hpp"
#include "theorem1.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

std::string fmt(double v) { return hinf::significant_text(v, 10); }

// Pre-flight (docs/maths.md [D10]): the error system contains the plant state, so the plant
// must be Schur stable for every admissible F (docs/maths.md §2.5). Name the offending mode.
// The plant is the scaled one; its eigenvalues are computed balanced (docs/maths.md §4.4).
void preflight(const Plant& plant, const Settings& settings) {
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
                    "i); the filtering error contains the plant state, so no filter can make it "
                    "stable (docs/maths.md §2.5)");
  }
  if (plant.uncertain()) {
    // The zero filter's error system has the plant's A + HFE as its top-left block.
    Filter zero{MatrixXd::Zero(plant.n(), plant.n()), MatrixXd::Zero(plant.n(), plant.m()),
                MatrixXd::Zero(plant.l(), plant.n())};
    const certify::StabilitySample s =
        certify::sampled_robust_stability(plant, zero, settings.stability_samples, settings.seed);
    if (!(s.max_spectral_radius < 1.0)) {
      throw Error(ErrorCode::Infeasible,
                  "plant is not robustly Schur stable: for an admissible F (‖F‖ ≤ 1) the spectral "
                  "radius of A + H F E is " + fmt(s.max_spectral_radius) +
                  " (nominal " + fmt(rho) + "); reduce the uncertainty (H, E) or stabilise the plant");
    }
    // Robust stability is not enough: Theorem 1 needs a quadratic Lyapunov function for
    // every admissible F, i.e. ‖E (zI − A)⁻¹ H‖∞ < 1 (docs/maths.md §3.7, eq. (119)).
    const certify::GainWitness w = certify::uncertainty_gain_witness(plant.A, plant.H, plant.E);
    if (w.verified)
      throw Error(ErrorCode::Infeasible,
                  "infeasible, with a certificate: A + H F E is robustly Schur stable for the sampled F but not "
                  "quadratically stable — the uncertainty channel's gain ‖E (zI − A)⁻¹ H‖ is at least " +
                      fmt(w.gain_lower_bound) + " > 1 at θ = " + fmt(w.theta) +
                      " rad/sample (verified), so no Lyapunov matrix serves every admissible F and Theorem 1 has no "
                      "solution for any γ (docs/maths.md (119)); H∞ norm of that channel " + fmt(w.gain) +
                      " (scaling H or E by less than 1/" + fmt(w.gain) + " meets this necessary condition)");
  }
}

// The solver's own options from the user's settings (as Ceres builds Minimizer::Options).
sdp::Options solver_options(const Settings& settings) {
  sdp::Options o;
  o.lmi_margin = settings.lmi_margin;
  o.relative_gap_tol = settings.relative_gap_tol;
  o.barrier_growth = settings.barrier_growth;
  o.feasibility_radius = settings.feasibility_radius;
  o.max_newton_per_centering = settings.max_newton_per_centering;
  o.max_iterations = settings.max_iterations;
  o.time_limit_s = settings.time_limit_s;
  return o;
}

// Refuses, before anything of its size is allocated, an SDP whose solve would need more
// memory than solver.max_memory_mb (the solver's model, hinf/sdp/memory_model.hpp).
void require_memory(const lmi::LmiProblem& lmi, const Settings& settings, const char* what) {
  const double mib = sdp::estimated_peak_bytes(lmi.order(), lmi.num_params() + 2) / (1 << 20);
  if (mib <= settings.max_memory_mb) return;
  throw Error(ErrorCode::InvalidInput,
              std::string(what) + " has order " + std::to_string(lmi.order()) + " and " +
                  std::to_string(lmi.num_params()) + " variables; its solve needs about " + fmt(std::ceil(mib)) +
                  " MiB (the solver's memory model, docs/benchmarks.md \"Memory\"), above the limit max_memory_mb = " +
                  hinf::number_text(settings.max_memory_mb) +
                  " MiB of the solver settings; raise it on a machine with that memory, or reduce the plant's order",
              "max_memory_mb");
}

// Out of memory is a problem too large for the machine (or its ulimit -v), as the memory
// guard's refusal is: invalid input, not a numerical failure.
ErrorCode error_code_for(sdp::Status status) {
  if (status == sdp::Status::Infeasible) return ErrorCode::Infeasible;
  if (status == sdp::Status::OutOfMemory) return ErrorCode::InvalidInput;
  return ErrorCode::NumericalFailure;
}

// The robust analysis LMI docs/maths.md (50) (Lemma 1 with the S-procedure) for a fixed filter,
// minimising γ² by the barrier method (`analyze`; the certificate uses the bounded-real
// form of the same LMI instead, certify/scaled_bounded_real.hpp). Returns γ².
double solve_analysis(const Plant& user_plant, const Filter& user, const Settings& settings) {
  const PlantScaling sc = choose_scaling(user_plant);
  const AnalysisLmi A = build_analysis_lmi(scaled_plant(user_plant, sc), scaled_filter(user, sc));
  require_memory(A.lmi, settings, "the robust analysis LMI");
  const VectorXd c = A.lmi.cost_of(A.g);
  const sdp::Solution sol = sdp::minimize_linear(A.lmi, c, solver_options(settings));
  if (sol.status != sdp::Status::Solved)
    throw Error(error_code_for(sol.status), "robust analysis LMI (docs/maths.md (50)): " +
                                                std::string(sdp::status_message(sol.status)) +
                                                (sol.detail.empty() ? "" : ": " + sol.detail));
  return sol.objective / (sc.gamma_factor() * sc.gamma_factor());
}

}  // namespace

double robust_bound(const Plant& plant, const Filter& filter, const Settings& settings) {
  validate_plant(plant);
  settings.validate();
  return std::sqrt(solve_analysis(plant, filter, settings));
}

namespace {
// Checks 2–4 (docs/maths.md §7.2–§7.4) at γ; none uses the synthesis solver's numbers (§7).
// Plant, filter and γ are the scaled ones (an exact change of units, docs/maths.md (112)).
Certificate certify(const Plant& plant, const Filter& filter, double gamma, const Settings& settings) {
  Certificate c;
  c.gamma = gamma;
  c.norm_A_F = filter.A_F.norm();
  c.norm_B_F = filter.B_F.norm();
  c.norm_C_F = filter.C_F.norm();
  // check 2: Schur stability, nominal and sampled admissible F
  const StateSpace es = certify::error_system(plant, filter);  // nominal (F = 0)
  c.spectral_radius_nominal = certify::spectral_radius(es.A);
  const certify::StabilitySample ss =
      certify::sampled_robust_stability(plant, filter, settings.stability_samples, settings.seed);
  c.spectral_radius_sampled_max = ss.max_spectral_radius;
  c.stability_samples = ss.samples;
  c.schur_stable = c.spectral_radius_nominal < 1 && ss.max_spectral_radius < 1;
  if (!c.schur_stable) return c;  // the norms below are undefined
  // check 3: nominal H∞ norm by the symplectic-pencil algorithm (no LMI, no grid)
  const certify::HinfNorm hn = certify::discrete_hinf_norm(es, 1e-10);
  c.hinf_norm_nominal = hn.norm;
  c.hinf_norm_peak_frequency = hn.peak_frequency;
  c.hinf_norm_ok = hn.norm <= gamma;
  // check 4: the robust analysis LMI at γ, decided by the bounded-real lemma with the
  // best S-procedure multiplier (no SDP solver involved; certify/scaled_bounded_real.hpp)
  certify::ScaledBoundedReal robust(plant, es);
  const certify::ScaledBoundedRealTest br = robust.test(gamma);
  c.robust_feasible_at_gamma = br.feasible;
  c.robust_multiplier = br.lambda;
  c.robust_scaled_norm = br.scaled_norm;
  // (to 1e-7 relative, rounded up: it is reported, not used)
  c.robust_bound = br.feasible ? robust.gamma_at_multiplier(br.lambda, hn.norm, gamma, 1e-7) : INFINITY;
  c.passed = c.schur_stable && c.hinf_norm_ok && c.robust_feasible_at_gamma;
  return c;
}

// The certificate's numbers in the user's units (docs/maths.md (112)): norms and bounds
// divided by σ_in·σ_z, λ by (s·σ_z)²; spectral radii and ‖G_λ‖∞ are invariant. The LMI
// check and the recovery's conditioning stay those of the scaled (congruent) LMI.
Certificate in_user_units(Certificate c, const PlantScaling& s, const Filter& user) {
  const double f = s.gamma_factor(), ls = s.uncertainty * s.output;
  c.gamma /= f;
  c.hinf_norm_nominal /= f;
  c.robust_bound /= f;
  c.robust_multiplier /= ls * ls;
  c.norm_A_F = user.A_F.norm();
  c.norm_B_F = user.B_F.norm();
  c.norm_C_F = user.C_F.norm();
  return c;
}
}  // namespace

Certificate certify_filter(const Plant& plant, const Filter& filter, double gamma,
                           const Settings& settings) {
  validate_plant(plant);
  settings.validate();
  const PlantScaling sc = choose_scaling(plant);
  const Certificate c = certify(scaled_plant(plant, sc), scaled_filter(filter, sc), gamma * sc.gamma_factor(), settings);
  return in_user_units(c, sc, filter);
}

namespace {

// The solver's progress tagged with the SDP it belongs to (null stays null).
sdp::ProgressObserver staged(const IterationObserver& observer, SolveStage stage) {
  if (!observer) return nullptr;
  return [observer, stage](const sdp::Progress& p) { observer(IterationReport{stage, p}); };
}

// Phase I's verdict as a theorem (docs/maths.md (118)): Infeasible only with a verified dual
// certificate that no point makes the LMI negative definite; otherwise a numerical failure
// that reports the smallest violation reached.
Error infeasibility_verdict(const lmi::LmiProblem& lmi, const sdp::Solution& sol,
                            const std::vector<lmi::SparseEntry>& basis_error, const Settings& settings,
                            const std::string& what, const std::string& hint) {
  if (sol.phase1_path.empty())
    return Error(ErrorCode::NumericalFailure, what + ": phase I ended infeasible without a final point");
  const VectorXd& last = sol.phase1_path.back();
  const std::vector<VectorXd> earlier(sol.phase1_path.begin(), sol.phase1_path.end() - 1);
  const sdp::DualBound b = sdp::verified_infeasibility(lmi, last, settings.lmi_margin, basis_error, earlier);
  if (b.verified && b.lower_bound > 0)
    return Error(ErrorCode::Infeasible,
                 what + ": infeasible, with a certificate: a verified dual point Z ⪰ 0 (tr Z = 1, tr(Z Mᵢ) = 0) "
                        "proves that the largest eigenvalue of the LMI is at least " + fmt(b.lower_bound) +
                        " > 0 at every point (docs/maths.md (118))" + hint);
  return Error(ErrorCode::NumericalFailure,
               what + ": phase I ended with the smallest violation " + fmt(last(lmi.num_params())) +
                   " > 0 (largest eigenvalue of the LMI), but no certificate of infeasibility could be "
                   "verified (" + b.detail + "); the problem may be feasible only at infinity or be badly "
                   "conditioned");
}

// Corollary 1, docs/maths.md (21): minimise γ² subject to LMI (18). Throws with the
// solver's reason if it does not end Solved.
sdp::Solution solve_corollary1(const Theorem1Lmi& T, const std::vector<lmi::SparseEntry>& basis_error,
                               const Settings& settings, const IterationObserver& observer) {
  require_memory(T.lmi, settings, "the Theorem 1 LMI");
  const VectorXd c = T.lmi.cost_of(T.g);
  sdp::Solution sol = sdp::minimize_linear(T.lmi, c, solver_options(settings), VectorXd(),
                                           staged(observer, SolveStage::Synthesis));
  if (sol.status == sdp::Status::Solved) return sol;
  if (sol.status == sdp::Status::Infeasible)
    throw infeasibility_verdict(T.lmi, sol, basis_error, settings, "Theorem 1 LMI",
                                " (the plant is robustly Schur stable for the sampled F, but the uncertainty "
                                "bound H, E is too large for a quadratic certificate)");
  std::string msg = std::string("Theorem 1 LMI: ") + sdp::status_message(sol.status);
  if (!sol.detail.empty()) msg += ": " + sol.detail;
  throw Error(error_code_for(sol.status), msg);
}

// The γ back-off (docs/maths.md §6): at γ_b² = (1 + b)²·γ*², the point of largest LMI
// margin, which keeps S and R − S away from singular and the recovered gains moderate.
// The margin only has to be near its maximum (a well-centred point, not a digit count):
// relative accuracy 1e-3. At the solver's 1e-7 a margin of ~1e-6 would ask for an
// absolute gap of 1e-13, below round-off.
constexpr double kBackoffRelativeGap = 1e-3;

sdp::Solution solve_backoff(const Theorem1Lmi& Tb, double gamma2_backoff, const Settings& settings,
                            const IterationObserver& observer) {
  sdp::Options options = solver_options(settings);
  options.relative_gap_tol = std::max(settings.relative_gap_tol, kBackoffRelativeGap);
  const sdp::Solution sol = sdp::minimize_linear(Tb.lmi, Tb.lmi.cost_of(Tb.margin), options, VectorXd(),
                                                 staged(observer, SolveStage::Backoff));
  if (sol.status != sdp::Status::Solved || !(sol.objective < 0))
    throw Error(ErrorCode::NumericalFailure,
                std::string("gamma back-off: maximising the LMI margin at γ = ") + fmt(std::sqrt(gamma2_backoff)) +
                    " failed: " + sdp::status_message(sol.status) + (sol.detail.empty() ? "" : ": " + sol.detail));
  return sol;
}

// Checks 1–4 of the certificate (docs/maths.md §7) at the returned point. Only the
// rounding of the recovery (S⁻¹ near the boundary) can make the recovered filter miss
// check 4 by a hair; then it is tried once more at (1 + relative_gap_tol)·γ², still
// within the solver's accuracy.
void certify_result(const Plant& plant, const certify::Theorem1Point& pt, const Settings& settings,
                    SynthesisResult& res) {
  // check 1: LMI docs/maths.md (18) at the returned point (with g = certified γ²), assembled densely
  const certify::DefinitenessCheck lmi_check =
      certify::check_negative_definite(certify::theorem1_matrix(plant, pt), 0.0);
  res.gamma_squared = pt.g;
  res.certificate = certify(plant, res.filter, std::sqrt(pt.g), settings);
  if (res.certificate.schur_stable && !res.certificate.robust_feasible_at_gamma) {
    res.gamma_squared = pt.g * (1 + settings.relative_gap_tol);
    res.certificate = certify(plant, res.filter, std::sqrt(res.gamma_squared), settings);
  }
  res.gamma = std::sqrt(res.gamma_squared);
  Certificate& cert = res.certificate;
  cert.lmi_max_eig = lmi_check.max_eig;
  cert.lmi_max_eig_relative = lmi_check.max_eig_relative;
  cert.lmi_negative_definite = lmi_check.negative_definite;
  const VectorXd eig_S = Eigen::SelfAdjointEigenSolver<MatrixXd>(pt.S, Eigen::EigenvaluesOnly).eigenvalues();
  const VectorXd eig_RS =
      Eigen::SelfAdjointEigenSolver<MatrixXd>(pt.R - pt.S, Eigen::EigenvaluesOnly).eigenvalues();
  cert.cond_S = eig_S(eig_S.size() - 1) / eig_S(0);
  cert.cond_R_minus_S = eig_RS(0) > 0 ? eig_RS(eig_RS.size() - 1) / eig_RS(0) : INFINITY;
  cert.passed = cert.passed && cert.lmi_negative_definite;
}

// Why a certificate failed, check by check.
std::string failed_checks(const Certificate& cert, double gamma) {
  std::string why;
  if (!cert.lmi_negative_definite) why += " LMI (18) not negative definite (max eigenvalue " + fmt(cert.lmi_max_eig) + ");";
  if (!cert.schur_stable)
    why += " error system not Schur stable (spectral radius " +
           fmt(std::max(cert.spectral_radius_nominal, cert.spectral_radius_sampled_max)) + ");";
  if (cert.schur_stable && !cert.hinf_norm_ok)
    why += " nominal H∞ norm " + fmt(cert.hinf_norm_nominal) + " > γ " + fmt(gamma) + ";";
  if (cert.schur_stable && !cert.robust_feasible_at_gamma) why += " robust analysis LMI infeasible at γ;";
  return why;
}

}  // namespace

namespace {
// The optimality bracket of the user's problem (docs/maths.md §5.9): a lower bound on γ*²
// of the strict LMI (18) from a verified dual point, in the user's units (exact: ÷ 2^2k).
void record_bracket(const Theorem1Lmi& T, const std::vector<lmi::SparseEntry>& basis_error, const sdp::Solution& sol,
                    const Settings& settings, double f, SolverInfo& info) {
  const sdp::DualBound b = sdp::verified_bracket(T.lmi, T.lmi.cost_of(T.g), sol.x, settings.lmi_margin,
                                                 basis_error, sol.centred_path);
  info.gap_certified = b.verified && b.upper_verified;
  info.gap_detail = b.verified ? (b.upper_verified ? "" : "the solution point is not verifiably strictly feasible")
                               : b.detail;
  if (!info.gap_certified) return;
  info.dual_bound_gamma_squared = b.lower_bound / (f * f);
  info.relative_gap = (b.upper_bound - b.lower_bound) / b.upper_bound;
}

SolverInfo solver_info(const sdp::Solution& sol, const Theorem1Lmi& T, const PlantScaling& sc,
                       const Settings& settings) {
  SolverInfo info;
  info.status = sol.status;
  info.newton_iterations = sol.newton_total;
  info.phase1_iterations = sol.newton_phase1;
  info.centerings = sol.centerings;
  info.scaling = sc.summary();
  info.lmi_margin = settings.lmi_margin;
  info.time_s = sol.elapsed_s;
  info.lmi_order = T.lmi.order();
  info.variables = T.lmi.num_params();
  info.optimal_gamma = std::sqrt(sol.objective) / sc.gamma_factor();
  return info;
}
}  // namespace

// Every step runs on the scaled plant (docs/maths.md §4.4), an exact change of units; the
// filter and every reported number are mapped back to the user's units at the end.
SynthesisResult synthesize(const Plant& user_plant, const Settings& settings, const IterationObserver& observer) {
  validate_plant(user_plant);
  settings.validate();
  const PlantScaling sc = choose_scaling(user_plant);
  const Plant plant = scaled_plant(user_plant, sc);
  preflight(plant, settings);

  const Theorem1Lmi T = build_theorem1(plant);
  const std::vector<lmi::SparseEntry> basis_error = theorem1_basis_error(T, plant);
  const sdp::Solution sol = solve_corollary1(T, basis_error, settings, observer);
  SynthesisResult res;
  res.solver = solver_info(sol, T, sc, settings);
  record_bracket(T, basis_error, sol, settings, sc.gamma_factor(), res.solver);

  certify::Theorem1Point pt;
  if (settings.gamma_backoff > 0) {
    const double gamma2_backoff = sol.objective * (1 + settings.gamma_backoff) * (1 + settings.gamma_backoff);
    const Theorem1Lmi Tb = build_theorem1_backoff(plant, gamma2_backoff);
    const sdp::Solution sb = solve_backoff(Tb, gamma2_backoff, settings, observer);
    res.solver.newton_iterations += sb.newton_total;
    res.solver.time_s += sb.elapsed_s;
    pt = theorem1_point(Tb, plant, sb.x, gamma2_backoff);
  } else {
    pt = theorem1_point(T, plant, sol.x, sol.objective);
  }
  res.filter = recover_filter(pt);
  certify_result(plant, pt, settings, res);
  if (!res.certificate.passed)
    throw Error(ErrorCode::NumericalFailure,
                "certificate failed, no filter written:" + failed_checks(res.certificate, res.gamma));
  const double f = sc.gamma_factor();
  res.filter = user_filter(res.filter, sc);
  res.certificate = in_user_units(res.certificate, sc, res.filter);
  res.gamma /= f;
  res.gamma_squared /= f * f;
  return res;
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

}  // namespace hinf::synth
