// The steps every synthesis pipeline shares (docs/maths.md §5–§7): the solver's options,
// the memory guard, statuses as exit codes, phase I's verdict, the back-off solve, the
// certificate's checks 2–4, units, the optimality bracket and the solver's record.
#include "pipeline.hpp"

#include <cmath>

#include "hinf/certify/dense_lmi.hpp"
#include "hinf/certify/error_system.hpp"
#include "hinf/certify/h2_norm.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/scaled_bounded_real.hpp"
#include "hinf/certify/stability.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/sdp/dual_bound.hpp"
#include "hinf/sdp/memory_model.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;
using Eigen::VectorXd;

std::string fmt(double v) { return hinf::significant_text(v, 10); }

// Refuses, before anything of its size is allocated, an SDP whose solve would need more
// memory than solver.max_memory_mb (the solver's model, hinf/sdp/memory_model.hpp).
double estimated_solve_mib(const lmi::LmiProblem& lmi) {
  return sdp::estimated_peak_bytes(lmi.order(), lmi.num_params() + 2) / (1 << 20);
}

sdp::TimeEstimate estimated_solve_time(const lmi::LmiProblem& lmi) {
  return sdp::estimated_solve_time(lmi.hessian_multiply_adds(), lmi.num_params() + 2);
}

void require_memory(const lmi::LmiProblem& lmi, const Settings& settings, const char* what) {
  const double mib = estimated_solve_mib(lmi);
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
  const sdp::DualBound b = sdp::verified_infeasibility(lmi, last, settings.solver.lmi_margin, basis_error, earlier);
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

std::string structured_infeasible_hint() {
  return " (F is block-diagonal: this LMI, with one S-procedure multiplier per block, is a sufficient condition "
         "only, so its infeasibility does not prove that no filter exists; one full block "
         "(uncertainty_blocks: full) is more conservative still; reduce the parameters' ranges)";
}

sdp::Solution solve_min_gamma(const lmi::LmiProblem& lmi, lmi::VarId g, const std::vector<lmi::SparseEntry>& basis_error,
                              const Settings& settings, const IterationObserver& observer, const std::string& what,
                              const std::string& infeasible_hint, const std::string& failure_hint) {
  require_memory(lmi, settings, ("the " + what).c_str());
  // Near the boundary of feasibility the feasible set lies far out (the Lyapunov matrix,
  // the multiplier and γ* grow as the uncertainty channel's gain nears 1): a solve that
  // fails on round-off is retried in wider balls, keeping its best point (docs/maths.md §4.3).
  const sdp::Solution sol =
      sdp::minimize_in_wider_balls(lmi, lmi.cost_of(g), settings.solver, sdp::WiderBallsWhen::FailedOrStoppedShort,
                                   staged(observer, SolveStage::Synthesis));
  if (sdp::has_point(sol.status)) return sol;
  if (sol.status == sdp::Status::Infeasible)
    throw infeasibility_verdict(lmi, sol, basis_error, settings, what, infeasible_hint);
  std::string msg = what + ": " + sdp::status_message(sol.status);
  if (!sol.detail.empty()) msg += ": " + sol.detail;
  // phase I did not reach a strictly feasible point: say how far it got
  if (!sol.phase1_path.empty() && sol.phase1_path.back()(lmi.num_params()) >= 0)
    msg += "; phase I's smallest violation reached: " + fmt(sol.phase1_path.back()(lmi.num_params())) +
           " (largest eigenvalue of the LMI, must be < 0; neither feasibility nor infeasibility is certified)";
  throw Error(error_code_for(sol.status), msg + failure_hint);
}

// The γ back-off (docs/maths.md §6): at γ_b² = (1 + b)²·γ*², the point of largest LMI
// margin, which keeps S and R − S away from singular and the recovered gains moderate.

sdp::Solution solve_backoff(const lmi::LmiProblem& lmi, lmi::VarId margin, double gamma2_backoff, const Settings& settings,
                            const IterationObserver& observer) {
  sdp::Options options = settings.solver;
  options.relative_gap_tol = std::max(settings.solver.relative_gap_tol, kBackoffRelativeGap);
  const sdp::Solution sol = sdp::minimize_linear(lmi, lmi.cost_of(margin), options, VectorXd(),
                                                 staged(observer, SolveStage::Backoff));
  if (!sdp::has_point(sol.status) || !(sol.objective < 0))
    throw Error(ErrorCode::NumericalFailure,
                std::string("gamma back-off: maximising the LMI margin at γ = ") + fmt(std::sqrt(gamma2_backoff)) +
                    " failed: " + sdp::status_message(sol.status) + (sol.detail.empty() ? "" : ": " + sol.detail));
  return sol;
}

// An observer-form filter's A_F, B_F, C_F, G_F must be A − K C, K, L, G to rounding: the
// certificate is of the error dynamics (122), which only that realisation has.
constexpr double kObserverMismatchTolerance = 1e-12;

// Checks 2–4 (docs/maths.md §7.2–§7.4) at γ; none uses the synthesis solver's numbers (§7).
// Plant, filter and γ are the scaled ones (an exact change of units, docs/maths.md (112)).
Certificate certify_checks(const Plant& plant, const Filter& filter, double gamma, const Settings& settings,
                           const Eigen::VectorXd& multipliers) {
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
  c.h2_norm_nominal = certify::discrete_h2_norm(es);
  // check 4: the robust analysis LMI at γ, decided by the bounded-real lemma with the
  // best S-procedure multiplier (no SDP solver involved; certify/scaled_bounded_real.hpp)
  certify::ScaledBoundedReal robust(plant, es);
  const certify::ScaledBoundedRealTest br = robust.test(gamma, true, multipliers);
  c.robust_feasible_at_gamma = br.feasible;
  c.robust_multiplier = br.lambda;
  if (plant.structured()) c.robust_block_multipliers = br.multipliers;
  c.robust_scaled_norm = br.scaled_norm;
  // (to 1e-7 relative, rounded up: it is reported, not used)
  c.robust_bound = br.feasible ? robust.gamma_at_multiplier(br.lambda, hn.norm, gamma, 1e-7) : INFINITY;
  c.passed = c.schur_stable && c.hinf_norm_ok && c.robust_feasible_at_gamma;
  if (filter.form == FilterForm::Observer) {
    c.observer_mismatch = certify::observer_form_mismatch(plant, filter);
    c.passed = c.passed && c.observer_mismatch <= kObserverMismatchTolerance;
  }
  return c;
}

namespace {

// The γ written is the smallest the certificate proves (docs/maths.md §7.5): check 4's root
// γ_λ at its multiplier (robust_bound), when a back-off or the recovery left room below the
// LMI's level. Checks 2–4 are run again there (check 4 choosing its multiplier afresh at
// that γ, whose root is lower again) while the bound falls and every check passes; check 1
// stays the LMI's at the returned point, at its own level.
constexpr int kTighteningRounds = 10;
void tighten_to_certified_bound(const Plant& plant, const Settings& settings, const Eigen::VectorXd& multipliers,
                                SynthesisResult& res) {
  for (int round = 0; round < kTighteningRounds; ++round) {
    const double bound = res.certificate.robust_bound;
    if (!res.certificate.passed || !(bound < res.gamma) || !(bound > 0)) return;
    const Certificate tight = certify_checks(plant, res.filter, bound, settings, multipliers);
    if (!tight.passed) return;
    res.certificate = tight;
    res.gamma = bound;
    res.gamma_squared = bound * bound;
  }
}

}  // namespace

// Check 1 (the LMI assembled densely at the returned point, with g = the certified γ²) and
// checks 2–4. Only the rounding of the recovery (S⁻¹ or P⁻¹ near the boundary) can make the
// recovered filter miss check 4 by a hair; then it is tried once more at
// (1 + relative_gap_tol)·γ², still within the solver's accuracy.
void certify_at_point(const Plant& plant, const MatrixXd& dense_lmi, double g, const Settings& settings,
                      const Eigen::VectorXd& multipliers, SynthesisResult& res) {
  const certify::DefinitenessCheck lmi_check = certify::check_negative_definite(dense_lmi, 0.0);
  res.gamma_squared = g;
  res.certificate = certify_checks(plant, res.filter, std::sqrt(g), settings, multipliers);
  if (res.certificate.schur_stable && !res.certificate.robust_feasible_at_gamma) {
    res.gamma_squared = g * (1 + settings.solver.relative_gap_tol);
    res.certificate = certify_checks(plant, res.filter, std::sqrt(res.gamma_squared), settings, multipliers);
  }
  res.gamma = std::sqrt(res.gamma_squared);
  tighten_to_certified_bound(plant, settings, multipliers, res);
  Certificate& cert = res.certificate;
  cert.lmi_max_eig = lmi_check.max_eig;
  cert.lmi_max_eig_relative = lmi_check.max_eig_relative;
  cert.lmi_negative_definite = lmi_check.negative_definite;
  cert.passed = cert.passed && cert.lmi_negative_definite;
}

// The certificate's numbers in the user's units (docs/maths.md (112)): norms and bounds
// divided by σ_in·σ_z, λ by (s·σ_z)²; spectral radii and ‖G_λ‖∞ are invariant. The LMI
// check and the recovery's conditioning stay those of the scaled (congruent) LMI.
Certificate in_user_units(Certificate c, const PlantScaling& s, const Filter& user) {
  const double f = s.gamma_factor(), ls = s.uncertainty * s.output;
  c.gamma /= f;
  c.hinf_norm_nominal /= f;
  c.h2_norm_nominal /= f;
  c.robust_bound /= f;
  c.robust_multiplier /= ls * ls;
  c.robust_block_multipliers /= ls * ls;
  c.norm_A_F = user.A_F.norm();
  c.norm_B_F = user.B_F.norm();
  c.norm_C_F = user.C_F.norm();
  return c;
}

// Why a certificate failed, check by check.
std::string failed_checks(const Certificate& cert, double gamma) {
  std::string why;
  if (!cert.lmi_negative_definite) why += " LMI not negative definite (max eigenvalue " + fmt(cert.lmi_max_eig) + ");";
  if (!cert.schur_stable)
    why += " error system not Schur stable (spectral radius " +
           fmt(std::max(cert.spectral_radius_nominal, cert.spectral_radius_sampled_max)) + ");";
  if (cert.schur_stable && !cert.hinf_norm_ok)
    why += " nominal H∞ norm " + fmt(cert.hinf_norm_nominal) + " > γ " + fmt(gamma) + ";";
  if (cert.schur_stable && !cert.robust_feasible_at_gamma) why += " robust analysis LMI infeasible at γ;";
  if (cert.observer_mismatch > kObserverMismatchTolerance)
    why += " the realisation is not (A − K C, K, L, G) (relative difference " + fmt(cert.observer_mismatch) + ");";
  return why;
}

// The optimality bracket of the user's problem (docs/maths.md §5.9): a lower bound on γ*²
// of the strict LMI (18) from a verified dual point, in the user's units (exact: ÷ 2^2k).
void record_bracket(const lmi::LmiProblem& lmi, lmi::VarId g, const std::vector<lmi::SparseEntry>& basis_error, const sdp::Solution& sol,
                    const Settings& settings, double f, SolverInfo& info) {
  const sdp::DualBound b = sdp::verified_bracket(lmi, lmi.cost_of(g), sol.x, settings.solver.lmi_margin,
                                                 basis_error, sol.centred_path);
  info.gap_certified = b.verified && b.upper_verified;
  info.gap_detail = b.verified ? (b.upper_verified ? "" : "the solution point is not verifiably strictly feasible")
                               : b.detail;
  if (!info.gap_certified) return;
  info.dual_bound_gamma_squared = b.lower_bound / (f * f);
  info.relative_gap = (b.upper_bound - b.lower_bound) / b.upper_bound;
}

SolverInfo solver_info(const sdp::Solution& sol, const lmi::LmiProblem& lmi, const PlantScaling& sc,
                       const Settings& settings) {
  SolverInfo info;
  info.status = sol.status;
  info.newton_iterations = sol.newton_total;
  info.phase1_iterations = sol.newton_phase1;
  info.centerings = sol.centerings;
  info.scaling = sc.summary();
  info.lmi_margin = settings.solver.lmi_margin;
  info.time_s = sol.elapsed_s;
  info.lmi_order = lmi.order();
  info.variables = lmi.num_params();
  info.optimal_gamma = std::sqrt(sol.objective) / sc.gamma_factor();
  return info;
}

}  // namespace hinf::synth
