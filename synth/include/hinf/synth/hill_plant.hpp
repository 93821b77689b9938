// The paper's chaser-navigation plant as a synthesis problem (docs/maths.md §9): the
// Hill/CW model of models/hill.hpp with a known orbit-control law u = K x, an uncertain
// orbital rate ω = ω₀(1+δ), |δ| ≤ δ̄, a discretisation with sample time T, and the noise,
// measurement and estimated-signal matrices. build_hill_plant() turns it into the discrete
// uncertain Plant of docs/maths.md (1)–(4):
//   A = discrete A of A_c = A₁(ω₀) + G₀K,  H = Γ·H_a,  E = E_a(δ̄)
// exact for Euler (A + H F(δ) E = I + T(A₁(ω₀(1+δ)) + G₀K) for every |δ| ≤ δ̄), a
// first-order uncertainty model for ZOH (models/hill.hpp says how far off).
//
// δ̄ = 0 means no uncertainty: the plant then has H n×0 and E 0×n (Plant::uncertain()
// is false) rather than an all-zero E.
#pragma once
#include <Eigen/Dense>

#include "hinf/models/hill.hpp"
#include "hinf/models/plant.hpp"

namespace hinf::synth {

// The physical description from which the plant is built (the config's `hill:` section).
struct HillPlantSpec {
  double orbital_rate = 0;  // ω₀, rad/s
  double chaser_mass = 0;   // m, kg
  Eigen::MatrixXd K;        // 3×6 orbit-control gain u = K x (N per m, N per m/s); empty = no control
  double sample_time = 0;   // T, s
  double delta_bar = 0;     // δ̄ ≥ 0: |δ| ≤ δ̄ with ω = ω₀(1+δ)
  hinf::models::Discretisation discretisation = hinf::models::Discretisation::Euler;
  Eigen::MatrixXd B;  // 6×p process-noise input of the discrete plant
  Eigen::MatrixXd D;  // m×q measurement-noise input
  Eigen::MatrixXd C;  // m×6 measurement matrix; empty = the paper's [I₃ 0₃]
  Eigen::MatrixXd L;  // l×6 estimated signal; empty = the paper's I₆
};

// F(δ) of docs/maths.md (69) (6×6). Throws Error(InvalidInput) unless δ̄ > 0 and |δ| ≤ δ̄
// (F is only admissible, ‖F‖ ≤ 1, inside that range).
Eigen::MatrixXd hill_uncertainty_F(double delta, double delta_bar);

// Checks every field (physical values, shapes); throws Error(InvalidInput) naming the
// field as a config key ("hill.chaser_mass = -1: must be > 0 (kg)").
void validate_hill_model(const HillPlantSpec& model);

// The discrete uncertain plant of the model (see the discretisations above).
// Validates the model first. The result satisfies validate_plant().
Plant build_hill_plant(const HillPlantSpec& model);

// The exact discrete A for a given δ (no first-order model):
//   euler: I + T(A₁(ω₀(1+δ)) + G₀K),   zoh: exp(T(A₁(ω₀(1+δ)) + G₀K)).
// For euler, build_hill_plant's A + H·hill_uncertainty_F(δ, δ̄)·E equals it for |δ| ≤ δ̄.
Eigen::MatrixXd hill_exact_discrete_A(const HillPlantSpec& model, double delta);

}  // namespace hinf::synth
