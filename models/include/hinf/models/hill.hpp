// Hill / Clohessy–Wiltshire relative motion, written once for the synthesis, the runtime
// filters and the simulator (docs/maths.md §9, with the source paper's misprints
// corrected). State x = [x, y, z, ẋ, ẏ, ż] (x radial, z orbit normal), thrust
// u = [F_x, F_y, F_z] in N:
//
//     ẍ = 3ω²x + 2ωẏ + F_x/m,   ÿ = −2ωẋ + F_y/m,   z̈ = −ω²z + F_z/m
//
//     A₁(ω) = [0 I; A₂₁ A₂₂],  A₂₁ = diag(3ω², 0, −ω²),  A₂₂ = [0 2ω 0; −2ω 0 0; 0 0 0]
//     G₀    = [0₃ₓ₃; I₃/m]
//
// With a known orbit-control law u = K x the continuous closed loop is A_c = A₁ + G₀K; an
// external thrust u_ext enters through G₀ in addition: ẋ = A_c x + G₀ u_ext.
//
// Uncertain orbital rate ω = ω₀(1 + δ), |δ| ≤ δ̄ (docs/maths.md (67)–(69)):
//     A₁(ω₀(1+δ)) − A₁(ω₀) = H_a F(δ) E_a  exactly, F(δ)ᵀF(δ) ≤ I,
//     H_a(4,1) = 3ω₀, H_a(4,5) = 2, H_a(5,4) = −2, H_a(6,3) = −ω₀  (1-based, else 0)
//     E_a = diag(ω₀(2δ̄+δ̄²), 0, ω₀(2δ̄+δ̄²), ω₀δ̄, ω₀δ̄, 0)
//     F(δ) = diag(c, 0, c, δ/δ̄, δ/δ̄, 0),  c = (2δ+δ²)/(2δ̄+δ̄²)
//
// Discretisation with sample time T (docs/maths.md (70)–(74)):
//   Euler (the paper's):  A = I + T A_c,  G = T G₀,  Γ = T·I
//   ZeroOrderHold:        exp(T [A_c I; 0 0]) = [e^{T A_c} Γ; 0 I],  Γ = ∫₀ᵀ e^{A_c s} ds,  G = Γ G₀
// and the discrete uncertainty ΔA = H F(δ) E with H = Γ H_a, E = E_a: exact for Euler, a
// first-order model for ZOH (the factor e^{A_c s} on the right of ΔA₁ inside the integral
// is dropped; residual O(T²‖A_c‖‖ΔA₁‖), ~1.3e-3 of ‖ΔA‖ for the paper's plant).
#pragma once

#include <Eigen/Dense>

#include "hinf/models/discretise.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hinf::models {

namespace hill {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix63 = Eigen::Matrix<double, 6, 3>;

// A₁(ω), any finite ω (used with ω = ω₀(1+δ)).
inline Matrix6 continuous_A(double w) {
  Matrix6 A = Matrix6::Zero();
  A.topRightCorner<3, 3>().setIdentity();
  A(3, 0) = 3.0 * w * w;  // A₂₁ = diag(3ω², 0, −ω²)
  A(5, 2) = -w * w;
  A(3, 4) = 2.0 * w;      // A₂₂ = [0 2ω 0; −2ω 0 0; 0 0 0]
  A(4, 3) = -2.0 * w;
  return A;
}

// G₀ = [0₃ₓ₃; I₃/m].
inline Matrix63 input_matrix(double m) {
  Matrix63 G = Matrix63::Zero();
  G.bottomRows<3>() = Eigen::Matrix3d::Identity() / m;
  return G;
}

inline Matrix6 uncertainty_H_a(double w0) {
  Matrix6 H = Matrix6::Zero();
  H(3, 0) = 3 * w0;  // H_a(4,1) = 3ω₀
  H(3, 4) = 2;       // H_a(4,5) = 2
  H(4, 3) = -2;      // H_a(5,4) = −2
  H(5, 2) = -w0;     // H_a(6,3) = −ω₀
  return H;
}

// E_a(δ̄); its (4,4) entry is ω₀δ̄ (the paper prints ω₀δ, docs/maths.md §16).
inline Matrix6 uncertainty_E_a(double w0, double delta_bar) {
  const double quadratic = w0 * (2 * delta_bar + delta_bar * delta_bar);
  const double linear = w0 * delta_bar;
  Eigen::Matrix<double, 6, 1> d;
  d << quadratic, 0, quadratic, linear, linear, 0;
  return d.asDiagonal();
}

// F(δ); admissible (‖F‖ ≤ 1) only for δ̄ > 0 and |δ| ≤ δ̄, which the caller checks.
inline Matrix6 uncertainty_F(double delta, double delta_bar) {
  const double c = (2 * delta + delta * delta) / (2 * delta_bar + delta_bar * delta_bar);
  const double r = delta / delta_bar;
  Eigen::Matrix<double, 6, 1> d;
  d << c, 0, c, r, r, 0;
  return d.asDiagonal();
}

// The discrete model of ẋ = A_c x + G₀ u (u held over a sample) and the map Γ of a
// perturbation of A_c into the discrete A (above).
struct Discrete {
  Matrix6 A;
  Matrix63 G;
  Matrix6 Gamma;
};

// The generic sampling of discretise.hpp (Euler and ZOH as above; Tustin is not offered
// for the Hill model).
inline Discrete discretise(const Matrix6& A_c, const Matrix63& G_0, double T, Discretisation d) {
  const SampledMatrices s = models::discretise(A_c, T, d);
  Discrete out;
  out.A = s.A;
  out.Gamma = s.Gamma;
  out.G = out.Gamma * G_0;
  return out;
}

}  // namespace hill

// The discrete Hill model as a process model of the runtime filters: f(x, u) = A x + G u,
// Jacobian F = A (the model is linear), and the structure H F(δ) E of its uncertainty.
class HillModel {
 public:
  static constexpr int NX = 6;
  static constexpr int NU = 3;
  using State = Eigen::Matrix<double, 6, 1>;
  using Input = Eigen::Matrix<double, 3, 1>;
  using StateMatrix = Eigen::Matrix<double, 6, 6>;
  using InputMatrix = Eigen::Matrix<double, 6, 3>;
  using Gain = Eigen::Matrix<double, 3, 6>;

  // No orbit control (K = 0). Throws std::invalid_argument on invalid parameters.
  HillModel(double orbital_rate, double mass, double sample_time,
            Discretisation discretisation = Discretisation::Euler)
      : HillModel(orbital_rate, mass, sample_time, Gain::Zero(), discretisation) {}

  // Orbit control u = K x included in the dynamics.
  HillModel(double orbital_rate, double mass, double sample_time, const Gain& K,
            Discretisation discretisation = Discretisation::Euler)
      : w_(orbital_rate), m_(mass), T_(sample_time), K_(K), disc_(discretisation) {
    if (!std::isfinite(w_) || w_ < 0.0)
      throw std::invalid_argument("HillModel: orbital_rate must be finite and >= 0 rad/s; got " + std::to_string(w_));
    if (!std::isfinite(m_) || m_ <= 0.0)
      throw std::invalid_argument("HillModel: mass must be finite and > 0 kg; got " + std::to_string(m_));
    if (!std::isfinite(T_) || T_ <= 0.0)
      throw std::invalid_argument("HillModel: sample_time must be finite and > 0 s; got " + std::to_string(T_));
    if (!K_.allFinite()) throw std::invalid_argument("HillModel: K (3x6) has a non-finite entry");
    A_1_ = hill::continuous_A(w_);
    G_0_ = hill::input_matrix(m_);
    A_c_ = A_1_ + G_0_ * K_;
    const hill::Discrete d = hill::discretise(A_c_, G_0_, T_, disc_);
    A_ = d.A;
    G_ = d.G;
    Gamma_ = d.Gamma;
  }

  // Continuous dynamics ẋ = A_c x + G₀ u (u = external thrust, N).
  State xdot(const State& x, const Input& u) const { return A_c_ * x + G_0_ * u; }

  // Discrete process function and its Jacobian.
  State f(const State& x, const Input& u) const { return A_ * x + G_ * u; }
  const StateMatrix& F(const State& /*x*/, const Input& /*u*/) const { return A_; }

  // The discrete uncertainty ΔA = H F(δ) E for |δ| ≤ δ̄: H = Γ H_a, E = E_a(δ̄).
  StateMatrix uncertainty_H() const { return Gamma_ * hill::uncertainty_H_a(w_); }
  StateMatrix uncertainty_E(double delta_bar) const { return hill::uncertainty_E_a(w_, delta_bar); }

  const StateMatrix& A() const { return A_; }      // discrete state matrix
  const InputMatrix& G() const { return G_; }      // discrete thrust input matrix
  const StateMatrix& Gamma() const { return Gamma_; }
  const StateMatrix& A_c() const { return A_c_; }  // A₁ + G₀K
  const StateMatrix& A_1() const { return A_1_; }
  const InputMatrix& G_0() const { return G_0_; }
  const Gain& K() const { return K_; }
  double orbital_rate() const { return w_; }
  double mass() const { return m_; }
  double sample_time() const { return T_; }
  Discretisation discretisation() const { return disc_; }

 private:
  double w_, m_, T_;
  Gain K_;
  Discretisation disc_;
  StateMatrix A_1_, A_c_, A_, Gamma_;
  InputMatrix G_0_, G_;
};

}  // namespace hinf::models
