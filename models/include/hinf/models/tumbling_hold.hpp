// Holding a point fixed in the body frame of a spinning or tumbling target (docs/maths.md
// §27): the relative motion ρ of a servicer in the target frame t, which turns at ω (rad/s)
// with ω̇, under the servicer's thrust F (N), mass m:
//   ρ̈ = −2 ω×ρ̇ − ω̇×ρ − ω×(ω×ρ) + G_t ρ + F/m + a_d                               (155)
// (G_t the gravity-gradient tensor, docs/maths.md (156)). The design model (157) freezes ω, ω̇ at
// their nominal values and leaves G_t to the robust channel:
//   x = [ρ − ρ*; ρ̇],  A = [0 I; K 2W],  K = −[ω̇×] − [ω×]²,  W = −[ω×],  B = [0; I/m];
// holding ρ* needs the equilibrium force U* = −m K ρ* (158). The generalised plant (159) adds
// the weighted outputs z = [W_p(ρ − ρ*); W_v ρ̇; W_u U] (and W_i ξ, ξ̇ = −ε ξ + ρ − ρ*, with
// integral action) and the inputs w = [s_d d; s_v ν] (ν only with the measurement-noise channel).
// Needs Eigen only.
#pragma once
#include <Eigen/Dense>
#include <cmath>

#include "hinf/models/attitude.hpp"
#include "hinf/models/discretise.hpp"
#include "hinf/models/generalised_plant.hpp"

namespace hinf::models {

// K of (157): the stiffness of the rotating frame, ρ̈ = K ρ + 2W ρ̇ + F/m.
inline Eigen::Matrix3d rotating_frame_stiffness(const Eigen::Vector3d& omega, const Eigen::Vector3d& omega_dot) {
  const Eigen::Matrix3d w = cross_matrix(omega);
  return -cross_matrix(omega_dot) - w * w;
}

// U* of (158): the constant thrust that holds ρ* in the frozen model.
inline Eigen::Vector3d equilibrium_force(double mass, const Eigen::Vector3d& omega, const Eigen::Vector3d& omega_dot,
                                         const Eigen::Vector3d& hold_point) {
  return -mass * rotating_frame_stiffness(omega, omega_dot) * hold_point;
}

struct TumblingHoldModel {
  double servicer_mass = 500.0;                       // m, kg
  Eigen::Vector3d target_rate{0, 0, 2 * kRadiansPerDegree};  // ω₀, rad/s (flat spin at 2 °/s)
  Eigen::Vector3d target_accel = Eigen::Vector3d::Zero();  // ω̇₀, rad/s²
  double orbit_rate = 1.1016e-3;     // n, rad/s: |G_t| ≤ 3n² (robust channel only)
  double disturbance_sigma = 1e-4;   // s_d, m/s²
  double measurement_sigma = 0.01;   // s_v, m
  bool measurement_noise_channel = true;  // ν in w (false: D21 = 0, a singular problem)
  double position_weight = 1.0;      // W_p, 1/m
  double velocity_weight = 0.0;      // W_v, s/m
  double force_weight = 0.8;         // W_u, 1/N
  bool integral_action = false;      // ξ̇ = −ε ξ + (ρ − ρ*) in the plant, W_i ξ in z
  double integral_weight = 0.01;     // W_i, 1/(m s)
  double integral_leak = 1e-3;       // ε, rad/s (a pure integrator is undetectable from y)
};

// The continuous-time generalised plant (159) of the model.
inline hinf::GeneralisedPlant tumbling_hold_plant(const TumblingHoldModel& m) {
  using Eigen::MatrixXd;
  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  const int ni = m.integral_action ? 3 : 0;
  const int n = 6 + ni, nw = m.measurement_noise_channel ? 6 : 3;
  const int nz = 9 + ni;
  hinf::GeneralisedPlant P;
  P.time = hinf::TimeDomain::Continuous;
  P.A = MatrixXd::Zero(n, n);
  P.A.block(0, 3, 3, 3) = I3;
  P.A.block(3, 0, 3, 3) = rotating_frame_stiffness(m.target_rate, m.target_accel);
  P.A.block(3, 3, 3, 3) = -2 * cross_matrix(m.target_rate);
  P.B1 = MatrixXd::Zero(n, nw);
  P.B1.block(3, 0, 3, 3) = m.disturbance_sigma * I3;
  P.B2 = MatrixXd::Zero(n, 3);
  P.B2.block(3, 0, 3, 3) = I3 / m.servicer_mass;
  P.C1 = MatrixXd::Zero(nz, n);
  P.C1.block(0, 0, 3, 3) = m.position_weight * I3;
  P.C1.block(3, 3, 3, 3) = m.velocity_weight * I3;
  P.D12 = MatrixXd::Zero(nz, 3);
  P.D12.block(6, 0, 3, 3) = m.force_weight * I3;
  if (m.integral_action) {
    P.A.block(6, 0, 3, 3) = I3;
    P.A.block(6, 6, 3, 3) = -m.integral_leak * I3;
    P.C1.block(9, 6, 3, 3) = m.integral_weight * I3;
  }
  P.C2 = MatrixXd::Zero(3, n);
  P.C2.block(0, 0, 3, 3) = I3;
  P.D11 = MatrixXd::Zero(nz, nw);
  P.D21 = MatrixXd::Zero(3, nw);
  if (m.measurement_noise_channel) P.D21.block(0, 3, 3, 3) = m.measurement_sigma * I3;
  return P;
}

// What the frozen model (157) does not know: |δω| ≤ rate, |δω̇| ≤ accel (rad/s, rad/s²) about
// ω₀, ω̇₀, and the gravity gradient G_t when asked.
struct TumblingHoldUncertainty {
  double rate = 0;
  double accel = 0;
  bool gravity_gradient = true;
};

// The channel ΔA = H F E of (160): the perturbation of the acceleration rows,
// [ΔK 2ΔW] = [e1 F1, e2 F2] with ‖ΔK‖ ≤ 2|ω₀||δω| + |δω|² + |δω̇| (+ 3n²), ‖2ΔW‖ ≤ 2|δω|, and
// e1, e2 those bounds times √2, so that F = [F1 F2] has ‖F‖ ≤ 1.
inline hinf::UncertaintyChannel tumbling_hold_uncertainty(const TumblingHoldModel& m, const TumblingHoldUncertainty& u,
                                                          int n) {
  const double w0 = m.target_rate.norm();
  const double stiffness = 2 * w0 * u.rate + u.rate * u.rate + u.accel +
                           (u.gravity_gradient ? 3 * m.orbit_rate * m.orbit_rate : 0.0);
  const double e1 = std::sqrt(2.0) * stiffness, e2 = std::sqrt(2.0) * 2 * u.rate;
  hinf::UncertaintyChannel c;
  c.H = Eigen::MatrixXd::Zero(n, 3);
  c.H.block(3, 0, 3, 3).setIdentity();
  c.E = Eigen::MatrixXd::Zero(6, n);
  c.E.block(0, 0, 3, 3) = e1 * Eigen::Matrix3d::Identity();
  c.E.block(3, 3, 3, 3) = e2 * Eigen::Matrix3d::Identity();
  return c;
}

// The plant sampled with period T (zero-order hold of w and u; z and y as sampled), for a
// controller designed in discrete time.
inline hinf::GeneralisedPlant sampled_plant(const hinf::GeneralisedPlant& continuous, double T) {
  const SampledMatrices s = discretise(continuous.A, T, Discretisation::ZeroOrderHold);
  hinf::GeneralisedPlant P = continuous;
  P.time = hinf::TimeDomain::Discrete;
  P.sample_time = T;
  P.A = s.A;
  P.B1 = s.Gamma * continuous.B1;
  P.B2 = s.Gamma * continuous.B2;
  return P;
}

}  // namespace hinf::models
