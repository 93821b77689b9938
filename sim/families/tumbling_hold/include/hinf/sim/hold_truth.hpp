// The truth of a tumbling_hold run (docs/maths.md (155), (156)): the servicer's position ρ
// and velocity ρ̇ relative to the target, in the target's body frame t, under two-body
// gravity (exact difference, not linearised) and the thrust F (in t; the servicer's
// attitude is slaved to the target's); the target a torque-free rigid body (Euler's
// equations J ω̇ = −ω × J ω) whose centre is on a circular orbit of rate n. RK4 with the
// thrust held over the step.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "hinf/sim/hold_scenario.hpp"

namespace hinf::sim {

// y = [ρ (3), ρ̇ (3), q (4: w, x, y, z; t → inertial), ω (3)], and the time.
using HoldTruthVector = Eigen::Matrix<double, 13, 1>;

class HoldTruth {
 public:
  explicit HoldTruth(const HoldScenario& s);

  HoldTruthVector initial_state(const HoldScenario& s) const;
  // One RK4 step of length h from time t with the thrust F (N, in t) held; the quaternion
  // renormalised after the step.
  void step(HoldTruthVector& y, double t, const Eigen::Vector3d& F, double h) const;
  HoldTruthVector derivative(const HoldTruthVector& y, double t, const Eigen::Vector3d& F) const;
  Eigen::Vector3d omega_dot(const Eigen::Vector3d& omega) const;  // Euler's equations
  Eigen::Vector3d target_position(double t) const;                // r_t, inertial, m

 private:
  Eigen::Vector3d J_, J_inv_;
  double mu_, n_, radius_, mass_;
};

}  // namespace hinf::sim
