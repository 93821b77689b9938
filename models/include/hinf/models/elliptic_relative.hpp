// The linear relative motion about an elliptic reference orbit in its rotating LVLH frame,
// sampled for a filter (docs/maths.md §32.3). Header-only, Eigen only, fixed sizes.
//
//   Ẋ = A(t) X + B (U_T − U_C),  B = [0; I₃],  A(t) from r, θ̇, θ̈ of the reference    (219)
//   transitions over [t_k, t_k + Δt]                                                      (220)
//     frozen:           Φ_k = exp(A(t_k) Δt)                (the source's eqs. 4–5)
//     frozen_midpoint:  Φ_k = exp(A(t_k + Δt/2) Δt)
//     exact:            Φ̇ = A(t) Φ integrated by RK4 (`exact_substeps` steps)
//     cw:               exp(A_CW Δt), A_CW the Clohessy–Wiltshire matrix of the mean motion
//   Q_d = ∫₀^Δt e^{A s} G q Gᵀ e^{Aᵀ s} ds (Van Loan, discretise.hpp), Γ = ∫₀^Δt e^{A s} ds B,
//   both with the A the transition froze (the exact transition: A at the midpoint).      (221)
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "hinf/models/discretise.hpp"
#include "hinf/models/kepler.hpp"
#include "hinf/models/lvlh.hpp"

namespace hinf::models {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix63 = Eigen::Matrix<double, 6, 3>;

// (219)
inline Matrix6 elliptic_relative_A(const OrbitRates& o, double mu) {
  const double w = o.theta_dot, w2 = w * w, dw = o.theta_ddot;
  const double g = mu / (o.radius * o.radius * o.radius);
  Matrix6 A = Matrix6::Zero();
  A.topRightCorner<3, 3>().setIdentity();
  A.block<3, 3>(3, 0) << w2 + 2 * g, dw, 0,  //
      -dw, w2 - g, 0,                        //
      0, 0, -g;
  A(3, 4) = 2 * w;
  A(4, 3) = -2 * w;
  return A;
}

// The Clohessy–Wiltshire A of mean motion n: (219) with θ̇ = n, θ̈ = 0, μ/r³ = n².
inline Matrix6 clohessy_wiltshire_A(double n) {
  OrbitRates o;
  o.theta_dot = n;
  o.radius = 1;
  return elliptic_relative_A(o, n * n);
}

// The closed-form CW transition over dt (x radial, y along-track, z normal).
inline Matrix6 clohessy_wiltshire_transition(double n, double dt) {
  const double c = std::cos(n * dt), s = std::sin(n * dt);
  Matrix6 P;
  P << 4 - 3 * c, 0, 0, s / n, 2 * (1 - c) / n, 0,             //
      6 * (s - n * dt), 1, 0, -2 * (1 - c) / n, (4 * s - 3 * n * dt) / n, 0,  //
      0, 0, c, 0, 0, s / n,                                     //
      3 * n * s, 0, 0, c, 2 * s, 0,                             //
      -6 * n * (1 - c), 0, 0, -2 * s, 4 * c - 3, 0,             //
      0, 0, -n * s, 0, 0, c;
  return P;
}

enum class RelativeTransition { Frozen, FrozenMidpoint, Exact, Cw };

inline const char* to_string(RelativeTransition t) {
  switch (t) {
    case RelativeTransition::Frozen: return "frozen";
    case RelativeTransition::FrozenMidpoint: return "frozen_midpoint";
    case RelativeTransition::Exact: return "exact";
    case RelativeTransition::Cw: return "cw";
  }
  return "?";
}

// What the filter needs over one sample.
struct SampledRelativeStep {
  Matrix6 Phi;    // X(t_k + Δt) = Φ X(t_k) for the unforced model
  Matrix6 Qd;     // process noise of white acceleration of PSD q per axis, (221)
  Matrix63 Gamma; // the state change of an acceleration held over the sample, (221)
};

// The relative model about a reference orbit (the chaser's initial Keplerian orbit), t
// counted from the reference's epoch.
class EllipticRelativeModel {
 public:
  struct Options {
    RelativeTransition transition = RelativeTransition::Frozen;
    double process_noise_psd = 0.25;  // q, m²/s³ per axis
    int exact_substeps = 100;         // RK4 steps per sample of the exact transition
  };

  EllipticRelativeModel(const KeplerOrbit& reference, const Options& options) : ref_(reference), o_(options) {}

  Matrix6 A(double t) const { return elliptic_relative_A(orbit_rates(ref_.state(t)), ref_.mu()); }

  // Φ over [t, t + dt] (220).
  Matrix6 transition(double t, double dt) const {
    switch (o_.transition) {
      case RelativeTransition::Frozen: return (A(t) * dt).exp();
      case RelativeTransition::FrozenMidpoint: return (A(t + dt / 2) * dt).exp();
      case RelativeTransition::Cw: return (clohessy_wiltshire_A(ref_.mean_motion()) * dt).exp();
      case RelativeTransition::Exact: return exact_transition(t, dt, o_.exact_substeps);
    }
    return Matrix6::Identity();
  }

  // Φ, Q_d, Γ over [t, t + dt] (220), (221); Γ only when `with_input`.
  SampledRelativeStep step(double t, double dt, bool with_input) const {
    SampledRelativeStep s;
    s.Phi = transition(t, dt);
    const Matrix6 Ak = frozen_A(t, dt);
    Matrix6 W = Matrix6::Zero();
    W.bottomRightCorner<3, 3>() = o_.process_noise_psd * Eigen::Matrix3d::Identity();
    s.Qd = sampled_white_noise_intensity<6>(Ak, W, dt);
    s.Gamma.setZero();
    if (with_input) {
      Matrix6 Ad, integral;
      held_input_transition<6>(Ak, dt, Ad, integral);
      s.Gamma = integral.rightCols<3>();
    }
    return s;
  }

  // Φ̇ = A(t) Φ, Φ(t) = I, by RK4 over [t, t + dt] in n steps.
  Matrix6 exact_transition(double t, double dt, int n) const {
    const double h = dt / n;
    Matrix6 P = Matrix6::Identity();
    for (int i = 0; i < n; ++i) {
      const double ti = t + i * h;
      const Matrix6 A0 = A(ti), Am = A(ti + h / 2), A1 = A(ti + h);
      const Matrix6 k1 = A0 * P;
      const Matrix6 k2 = Am * (P + h / 2 * k1);
      const Matrix6 k3 = Am * (P + h / 2 * k2);
      const Matrix6 k4 = A1 * (P + h * k3);
      P += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return P;
  }

  const KeplerOrbit& reference() const { return ref_; }
  const Options& options() const { return o_; }

 private:
  // The A a transition holds over the sample (the exact one: its midpoint).
  Matrix6 frozen_A(double t, double dt) const {
    switch (o_.transition) {
      case RelativeTransition::Frozen: return A(t);
      case RelativeTransition::Cw: return clohessy_wiltshire_A(ref_.mean_motion());
      default: return A(t + dt / 2);
    }
  }

  KeplerOrbit ref_;
  Options o_;
};

}  // namespace hinf::models
