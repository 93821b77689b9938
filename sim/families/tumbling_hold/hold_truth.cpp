// HoldTruth (hold_truth.hpp): docs/maths.md (155)–(156) without linearisation.
#include "hinf/sim/hold_truth.hpp"

#include <cmath>

namespace hinf::sim {

HoldTruth::HoldTruth(const HoldScenario& s)
    : J_(s.inertia),
      J_inv_(s.inertia.cwiseInverse()),
      mu_(s.mu),
      n_(s.orbit_rate),
      radius_(std::cbrt(s.mu / (s.orbit_rate * s.orbit_rate))),
      mass_(s.servicer_mass) {}

HoldTruthVector HoldTruth::initial_state(const HoldScenario& s) const {
  HoldTruthVector y;
  y.segment<3>(0) = s.hold_point + s.initial_offset;
  y.segment<3>(3) = s.initial_velocity;
  y.segment<4>(6) << 1, 0, 0, 0;  // the target frame starts aligned with the inertial one
  y.segment<3>(10) = s.initial_rate;
  return y;
}

Eigen::Vector3d HoldTruth::omega_dot(const Eigen::Vector3d& w) const {
  return J_inv_.cwiseProduct(-w.cross(J_.cwiseProduct(w)));
}

Eigen::Vector3d HoldTruth::target_position(double t) const {
  return radius_ * Eigen::Vector3d(std::cos(n_ * t), std::sin(n_ * t), 0);
}

HoldTruthVector HoldTruth::derivative(const HoldTruthVector& y, double t, const Eigen::Vector3d& F) const {
  const Eigen::Vector3d rho = y.segment<3>(0), v = y.segment<3>(3), w = y.segment<3>(10);
  const Eigen::Quaterniond q(y(6), y(7), y(8), y(9));
  const Eigen::Matrix3d C_it = q.normalized().toRotationMatrix();
  const Eigen::Vector3d w_dot = omega_dot(w);
  // gravity difference (156) in inertial axes, exact
  const Eigen::Vector3d r_t = target_position(t), r_c = r_t + C_it * rho;
  const Eigen::Vector3d a_e = -mu_ * r_c / std::pow(r_c.norm(), 3) + mu_ * r_t / std::pow(r_t.norm(), 3);
  HoldTruthVector d;
  d.segment<3>(0) = v;
  d.segment<3>(3) = -2 * w.cross(v) - w_dot.cross(rho) - w.cross(w.cross(rho)) + C_it.transpose() * a_e + F / mass_;
  const Eigen::Quaterniond q_dot = q * Eigen::Quaterniond(0, w.x(), w.y(), w.z());  // q̇ = ½ q ⊗ (0, ω)
  d.segment<4>(6) << 0.5 * q_dot.w(), 0.5 * q_dot.x(), 0.5 * q_dot.y(), 0.5 * q_dot.z();
  d.segment<3>(10) = w_dot;
  return d;
}

void HoldTruth::step(HoldTruthVector& y, double t, const Eigen::Vector3d& F, double h) const {
  const HoldTruthVector k1 = derivative(y, t, F);
  const HoldTruthVector k2 = derivative(y + (h / 2) * k1, t + h / 2, F);
  const HoldTruthVector k3 = derivative(y + (h / 2) * k2, t + h / 2, F);
  const HoldTruthVector k4 = derivative(y + h * k3, t + h, F);
  y += (h / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
  y.segment<4>(6).normalize();
}

}  // namespace hinf::sim
