// Reference for the synthesis at ZERO uncertainty, independent of the LMI: the
// stationary discrete-time H∞ a priori filter (one-step predictor) by the
// game-theoretic / Krein-space Riccati equation of Hassibi, Sayed & Kailath
// ("Indefinite-Quadratic Estimation and Control", SIAM 1999; "Linear estimation in
// Krein spaces, Part II", IEEE TAC 41(1), 1996), cf. Nagpal & Khargonekar, "Filtering
// and smoothing in an H∞ setting", IEEE TAC 36(2), 1991.
//
// Plant (nominal, H and E ignored):  x(k+1) = A x + B w,  y = C x + D v,  z = L x.
// Estimate of z(k) from y(0..k−1) (docs/maths.md (6): z_F(k) = C_F x_F(k)). Cost: the ℓ₂ gain
// from τ = [w; v] to e = z − ẑ, zero initial state (the H∞ norm of the error system).
// Assumptions: R = D Dᵀ > 0 (D of full row rank; then min{‖v‖ : D v = r} = ‖r‖_{R⁻¹}, so only
// R matters). A need not be Schur stable: the central filter is in observer form, whose error
// e = x − x̂ obeys (A − K C, [B, −K D], L) (docs/maths.md (122)); for an unstable A the DARE has
// a stabilising solution only if (A, C) is detectable (and no mode on the unit circle is
// unreachable from w), which the test below decides.
//
// Level γ is achievable by a causal predictor iff (a priori conditions):
//   (i)  the DARE  P = A P Aᵀ + B Bᵀ − A P Hᵀ (R_γ + H P Hᵀ)⁻¹ H P Aᵀ,
//        H = [C; L], R_γ = diag(R, −γ² I), equivalently
//        P = B Bᵀ + A P (I + G P)⁻¹ Aᵀ,  G = Cᵀ R⁻¹ C − γ⁻² Lᵀ L,
//        has a stabilising solution P = Pᵀ ≥ 0 (A (I + P G)⁻¹ Schur stable), and
//   (ii) P⁻¹ − γ⁻² LᵀL > 0, i.e. γ² I − L P Lᵀ > 0.
// Central filter (predictor form): P̃ = (P⁻¹ − γ⁻² LᵀL)⁻¹ = P + P Lᵀ(γ²I − L P Lᵀ)⁻¹ L P,
//   K = A P̃ Cᵀ (R + C P̃ Cᵀ)⁻¹,  A_F = A − K C,  B_F = K,  C_F = L.
// As γ → ∞ this is the Kalman one-step predictor with Q = B Bᵀ, R = D Dᵀ.
//
// A posteriori (estimate of z(k) from y(0..k), docs/maths.md §18.6): the same DARE (i), and
//   (ii') P⁻¹ + Cᵀ R⁻¹ C − γ⁻² LᵀL > 0, i.e. γ² I − L P_f Lᵀ > 0, P_f = P − P Cᵀ (R + C P Cᵀ)⁻¹ C P
// (the inertia of R_e = R_γ + H P Hᵀ equals that of R_γ when y(k) is processed before the
// fictitious observation L x(k)). Central filter: x̂(k|k) = x̂ + M (y − C x̂),
// M = P Cᵀ (R + C P Cᵀ)⁻¹, x̂(k+1) = A x̂(k|k): K = A M, C_F = L − L M C, D_F = L M (143).
// The optimum over causal predictors equals the optimum of Theorem 1 at H = E = 0
// (both are a priori problems over full-order filters; see the report).
#pragma once
#include <Eigen/Dense>
#include <string>

#include "hinf/models/plant.hpp"

namespace hinf::certify {

struct HinfPredictorLevel {
  double gamma = 0;                     // level tested (+∞: Kalman predictor)
  bool feasible = false;                // (i) and (ii) hold numerically
  std::string reason;                   // why not, if !feasible
  Eigen::MatrixXd P;                    // stabilising DARE solution (if found)
  Filter filter;                        // central filter (if feasible)
  double closed_loop_spectral_radius = 0;  // ρ(A (I + P G)⁻¹)
  double min_eig_gamma2_minus_LPL = 0;     // λ_min(γ² I − L P Lᵀ), or of γ² I − L P_f Lᵀ (filtered); +∞ for γ = ∞
  double riccati_residual = 0;             // ‖DARE residual‖_F / max(1, ‖P‖_F)
};

// Riccati test at a given level (gamma = std::numeric_limits<double>::infinity() gives
// the Kalman predictor). Throws Error(InvalidInput) for bad dimensions, R not positive
// definite or gamma ≤ 0. The filter is returned in observer form (form, K, G_F set).
// estimate Filtered: the a posteriori conditions and central filter (ii') above.
HinfPredictorLevel hinf_predictor_at_level(const Plant& nominal, double gamma,
                                           Estimate estimate = Estimate::Predicted);

struct HinfPredictorOptimum {
  double gamma = 0;             // smallest level found feasible (upper end of the bracket)
  double gamma_infeasible = 0;  // largest level found infeasible, or the lower bound σ_max(L B)
  int bisection_steps = 0;
  HinfPredictorLevel at_gamma;  // Riccati solution and central filter at `gamma`
                                // (near-optimal central filters are ill-conditioned;
                                // use hinf_predictor_at_level with a backed-off γ)
};

// Bisection (geometric) on γ between σ_max(L B) (a lower bound: e(k) contains L B w(k−1),
// which y(0..k−1) does not see; 0 for the filtered estimate) and the H∞ norm of the Kalman
// predictor's (filter's) error system, until gamma ≤ (1 + rel_tol) · gamma_infeasible.
HinfPredictorOptimum optimal_hinf_predictor(const Plant& nominal, double rel_tol = 1e-9,
                                            Estimate estimate = Estimate::Predicted);
double optimal_hinf_predictor_gamma(const Plant& nominal, double rel_tol = 1e-9,
                                    Estimate estimate = Estimate::Predicted);

}  // namespace hinf::certify
