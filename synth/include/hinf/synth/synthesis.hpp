// Robust H∞ filter synthesis (docs/maths.md §3: Theorem 1 (18), Corollary 1 (21), recovery (22))
// and the independent certificate of its result.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "hinf/models/plant.hpp"
#include "hinf/synth/settings.hpp"
#include "hinf/common/error.hpp"
#include "hinf/sdp/path_following.hpp"
#include "hinf/sdp/status.hpp"

namespace hinf::synth {

// Results of the independent checks of docs/maths.md §7 (none reuses the solver's numbers).
struct Certificate {
  double gamma = 0;                       // the bound being certified
  // check 1: LMI docs/maths.md (18) at the returned point, assembled densely, on the scaled
  // plant (congruent to the user's LMI, docs/maths.md §4.4)
  double lmi_max_eig = 0;                 // largest eigenvalue of M(x) (must be < 0)
  double lmi_max_eig_relative = 0;        // ... divided by ‖M(x)‖₂
  bool lmi_negative_definite = false;     // Cholesky of −M(x) − margin·I succeeded
  // check 2: Schur stability of the error system
  double spectral_radius_nominal = 0;
  double spectral_radius_sampled_max = 0; // over sampled admissible F (incl. vertices)
  int stability_samples = 0;
  bool schur_stable = false;
  // check 3: nominal H∞ norm by a non-LMI algorithm
  double hinf_norm_nominal = 0;
  double hinf_norm_peak_frequency = 0;    // rad/sample
  bool hinf_norm_ok = false;
  // not a check: the RMS of the estimation error under unit white noise (w, v), the H2
  // norm of the nominal error system (docs/maths.md (132)); what a Kalman filter minimises
  double h2_norm_nominal = 0;
  // check 4: robust analysis LMI (Lemma 1 + S-procedure) for the fixed filter, decided by
  // the bounded-real lemma: feasible at γ iff ‖[C̄; √λĒ](zI − Ā)⁻¹[B̄/γ, H̄/√λ]‖∞ < 1
  // for some multiplier λ > 0
  bool robust_feasible_at_gamma = false;
  double robust_multiplier = 0;           // λ found (user's H, E units; 0 without uncertainty)
  Eigen::VectorXd robust_block_multipliers;  // F block-diagonal (§23): λ_b per block; empty otherwise
  double robust_scaled_norm = 0;          // certified ‖·‖∞ at that λ (< 1 iff feasible)
  // the smallest γ at which the analysis LMI is feasible with that λ (≤ γ; +inf if
  // infeasible at γ) — an upper bound on the robust ℓ₂ gain. `analyze` minimises over λ too.
  double robust_bound = 0;
  // observer form only (docs/maths.md (121)): the realisation (A_F, B_F, C_F, G_F) is
  // (A − K C, K, L, G) to rounding; the error system of checks 2–4 is built from K
  double observer_mismatch = 0;           // certify::observer_form_mismatch (relative)
  // conditioning of the recovery (docs/maths.md §6, [D6]): S and R − S of Theorem 1, or P
  // of the observer-form LMI (124) (the others stay 0)
  double cond_S = 0, cond_R_minus_S = 0, cond_P = 0;
  double norm_A_F = 0, norm_B_F = 0, norm_C_F = 0;
  bool passed = false;
};

struct SolverInfo {
  // how the filter was computed; an SDP's record below only when status is not NotRun
  std::string method = "log-det barrier path following, Newton steps by Ipopt";
  sdp::Status status = sdp::Status::NotRun;
  int newton_iterations = 0;       // Ipopt iterations, phase I + II
  int phase1_iterations = 0;
  int centerings = 0;              // outer barrier steps
  // the optimality bracket (docs/maths.md §5.9), when verified: γ*² of the strict LMI (18)
  // lies in [dual_bound_gamma_squared, optimal_gamma²]
  bool gap_certified = false;
  std::string gap_detail;          // why not, when not
  double relative_gap = 0;         // (optimal γ² − lower bound)/optimal γ² (if certified)
  double dual_bound_gamma_squared = 0;  // verified lower bound on γ*², user's units
  std::string scaling;             // PlantScaling::summary() of the scaling applied
  double lmi_margin = 0;           // ε of M(x) ⪯ −εI, on the scaled LMI
  double optimal_gamma = 0;        // √(optimal γ²) of Corollary 1, before back-off/certification
  double time_s = 0;
  int lmi_order = 0;               // N
  int variables = 0;
};

struct SynthesisResult {
  Filter filter;                  // filter.form says which formulation was solved
  std::string bound;              // what γ bounds, in words (bound_statement)
  double gamma = 0;
  double gamma_squared = 0;
  Certificate certificate;
  SolverInfo solver;
  // With filter.form: auto, when Theorem 1's augmented filter was infeasible and the observer
  // form was solved instead: why the augmented one was (its verdict); empty otherwise.
  std::string augmented_infeasible;
};

// What γ bounds for a filter of this form on a plant with or without uncertainty: which
// signal, from which inputs, for which uncertainty (docs/maths.md (13), (123)).
std::string bound_statement(FilterForm form, bool uncertain, Estimate estimate = Estimate::Predicted);

// The SDP `synthesize` would solve, known before it runs (for -v and the memory guard):
// its form, the LMI's order N and variables, and the solver's memory and time models' estimates.
struct ProblemSize {
  FilterForm form = FilterForm::Augmented;
  int lmi_order = 0;
  int variables = 0;
  double memory_mib = 0;  // sdp::estimated_peak_bytes, MiB
  // The solver's time model (sdp::estimated_solve_time): one Newton iteration, and the
  // solve at the fewest and most Newton iterations measured.
  double newton_iteration_s = 0, fewest_s = 0, most_s = 0;
};
ProblemSize problem_size(const Plant& plant, const Settings& settings);

// Full pipeline: pre-flight checks, solve, recovery, certification.
// Throws Error(Infeasible) with the reason (e.g. spectral radius) or
// Error(NumericalFailure) if the certificate fails; never returns an uncertified filter.
SynthesisResult synthesize(const Plant& plant, const Settings& settings);

// Progress of the interior-point solver, for an iteration table (`--verbose`): which SDP
// an iteration belongs to — Theorem 1 itself, or the optional γ back-off (largest LMI
// margin at (1+b)γ*) — and the solver's own progress record.
// Synthesis: a filter's LMI (min γ²); Backoff: its γ back-off; Controller: a controller's
// LMI (docs/maths.md §26: min γ of the equilibrated plant).
enum class SolveStage { Synthesis, Backoff, Controller };

struct IterationReport {
  SolveStage stage = SolveStage::Synthesis;
  sdp::Progress progress;
};
using IterationObserver = std::function<void(const IterationReport&)>;
SynthesisResult synthesize(const Plant& plant, const Settings& settings,
                           const IterationObserver& observer);

// Noise covariances of the Kalman predictor when they are not B Bᵀ and D Dᵀ (a config's
// `kalman: {Q, R}`): Q (n×n, symmetric positive semidefinite) of the process noise entering
// x(k+1), R (m×m, symmetric positive definite) of the measurement noise; an empty matrix
// means the plant's own (B Bᵀ or D Dᵀ).
struct KalmanNoise {
  Eigen::MatrixXd Q, R;
};
// Error(InvalidInput) naming Q or R (shape, symmetry, definiteness).
void validate_kalman_noise(const KalmanNoise& noise, const Plant& plant);

// The Kalman one-step predictor of the nominal plant (docs/maths.md §8.1 at γ = ∞, (133)):
// Q = B Bᵀ, R = D Dᵀ unless `noise` gives them, observer form (needs (A, C) detectable,
// R ≻ 0), with the certificate of §7 on the plant itself at the smallest γ it achieves (its
// nominal H∞ norm, or with uncertainty the robust analysis bound, each times 1 + 1e-7). No
// SDP is solved for the filter itself.
SynthesisResult kalman_predictor(const Plant& plant, const Settings& settings, const KalmanNoise& noise = {});

// Independent checks of docs/maths.md §7 for any filter against a plant at bound gamma.
// `lmi_point` checks (check 1) are only possible for synthesised filters and are
// skipped (left at defaults) here; checks 2–4 are computed.
Certificate certify_filter(const Plant& plant, const Filter& filter, double gamma,
                           const Settings& settings);

// The Theorem-1 LMI in SDPA sparse format (min γ² s.t. docs/maths.md (18), H/E balanced, λ' = λs²),
// for cross-checking γ* with any SDP solver.
std::string theorem1_sdpa(const Plant& plant, const std::string& comment);
// The LMI `solve` would minimise for this plant and settings.form (docs/maths.md §18.4):
// Theorem 1's, or the observer-form LMI (124), in SDPA sparse format.
std::string synthesis_sdpa(const Plant& plant, const Settings& settings, const std::string& comment);

// Robust analysis (docs/maths.md (50) and §7.5: Lemma 1 with the S-procedure):
// the smallest γ for which the analysis LMI is feasible for this filter (without
// uncertainty: the error system's H∞ norm, by the symplectic pencil). Error(Infeasible)
// when there is no such γ.
double robust_bound(const Plant& plant, const Filter& filter, const Settings& settings);

}  // namespace hinf::synth
