// The paper's chaser-navigation plant (SPEC §3): Clohessy–Wiltshire/Hill equations
// with a known orbit-control law u = K x, an uncertain orbital rate ω = ω₀(1+δ),
// |δ| ≤ δ̄, and a discretisation with sample time T.
//
// State x = [x, y, z, ẋ, ẏ, ż] (m, m/s; x radial, z orbit normal), thrust u (N).
//
//   A₁(ω) = [0 I; A₂₁ A₂₂],  A₂₁ = diag(3ω², 0, −ω²),  A₂₂ = [0 2ω 0; −2ω 0 0; 0 0 0]
//   G₀    = [0₃ₓ₃; I₃/m]
//   A_c   = A₁(ω₀) + G₀K                         (continuous closed loop)
//   ΔA₁   = A₁(ω₀(1+δ)) − A₁(ω₀) = H_a F(δ) E_a  (exact, SPEC §3)
//   H_a(4,1) = 3ω₀, H_a(4,5) = 2, H_a(5,4) = −2, H_a(6,3) = −ω₀  (1-based, else 0)
//   E_a   = diag(ω₀(2δ̄+δ̄²), 0, ω₀(2δ̄+δ̄²), ω₀δ̄, ω₀δ̄, 0)   (SPEC's correction: E_a(4,4) = ω₀δ̄)
//   F(δ)  = diag(c, 0, c, δ/δ̄, δ/δ̄, 0),  c = (2δ+δ²)/(2δ̄+δ̄²),  F(δ)ᵀF(δ) ≤ I for |δ| ≤ δ̄
//
// Discretisations:
//   euler (the paper's): A = I + T·A_c,  H = T·H_a,  E = E_a.
//       Exact: A + H F(δ) E = I + T(A₁(ω₀(1+δ)) + G₀K) for every |δ| ≤ δ̄.
//   zoh:   A = e^{T A_c},  H = Γ·H_a,  E = E_a,  Γ = ∫₀ᵀ e^{A_c s} ds,
//       Γ from the block exponential  exp(T [A_c I; 0 0]) = [e^{T A_c} Γ; 0 I].
//       This is a FIRST-ORDER model of the uncertainty, not exact: the true perturbation
//       e^{T(A_c+ΔA₁)} − e^{T A_c} = ∫₀ᵀ e^{A_c(T−s)} ΔA₁ e^{A_c s} ds + O(T²‖ΔA₁‖²)
//       is approximated by Γ ΔA₁ (the factor e^{A_c s} on the right is dropped), so
//       e^{T(A_c+ΔA₁)} − (A + H F E) = O(T²‖A_c‖‖ΔA₁‖) + O(T²‖ΔA₁‖²).
//       For the paper's plant (T = 0.1 s) the residual is ~1.3e-3 of ‖ΔA‖ (1-norm; about
//       1e-9 absolute at δ = ±0.05, 2e-8 at δ = ±1). Use euler for an exact uncertainty model.
//
// δ̄ = 0 means no uncertainty: the plant then has H n×0 and E 0×n (Plant::uncertain()
// is false) rather than an all-zero E.
#pragma once
#include <Eigen/Dense>

#include "hinf/synth/validate_plant.hpp"

namespace hinf::synth {

struct HillModel {
  double orbital_rate = 0;  // ω₀, rad/s
  double chaser_mass = 0;   // m, kg
  Eigen::MatrixXd K;        // 3×6 orbit-control gain u = K x (N per m, N per m/s); empty = no control
  double sample_time = 0;   // T, s
  double delta_bar = 0;     // δ̄ ≥ 0: |δ| ≤ δ̄ with ω = ω₀(1+δ)
  enum class Discretisation { Euler, Zoh } discretisation = Discretisation::Euler;
  Eigen::MatrixXd B;  // 6×p process-noise input of the discrete plant
  Eigen::MatrixXd D;  // m×q measurement-noise input
  Eigen::MatrixXd C;  // m×6 measurement matrix; empty = the paper's [I₃ 0₃]
  Eigen::MatrixXd L;  // l×6 estimated signal; empty = the paper's I₆
};

// The CW matrix A₁(ω) of SPEC §3 (6×6). Any finite ω (used with ω = ω₀(1+δ)).
Eigen::MatrixXd hill_continuous_A(double omega);

// G₀ = [0₃ₓ₃; I₃/m] (6×3).
Eigen::MatrixXd hill_input_matrix(double chaser_mass);

// H_a and E_a of SPEC §3 (6×6 each), such that A₁(ω₀(1+δ)) − A₁(ω₀) = H_a F(δ) E_a.
Eigen::MatrixXd hill_uncertainty_H_a(double orbital_rate);
Eigen::MatrixXd hill_uncertainty_E_a(double orbital_rate, double delta_bar);

// F(δ) = diag(c, 0, c, δ/δ̄, δ/δ̄, 0) of SPEC §3 (6×6). Throws Error(InvalidInput) unless
// δ̄ > 0 and |δ| ≤ δ̄ (F is only admissible, ‖F‖ ≤ 1, inside that range).
Eigen::MatrixXd hill_uncertainty_F(double delta, double delta_bar);

// Checks every field (physical values, shapes); throws Error(InvalidInput) naming the
// field as a config key ("hill.chaser_mass = -1: must be > 0 (kg)").
void validate_hill_model(const HillModel& model);

// The discrete uncertain plant of the model (see the discretisations above).
// Validates the model first. The result satisfies validate_plant().
Plant build_hill_plant(const HillModel& model);

// The exact discrete A for a given δ (no first-order model):
//   euler: I + T(A₁(ω₀(1+δ)) + G₀K),   zoh: exp(T(A₁(ω₀(1+δ)) + G₀K)).
// For euler, build_hill_plant's A + H·hill_uncertainty_F(δ, δ̄)·E equals it for |δ| ≤ δ̄.
Eigen::MatrixXd hill_exact_discrete_A(const HillModel& model, double delta);

}  // namespace hinf::synth
