// The tumbling_hold truth (sim/hold_truth.hpp) against physics it must obey, computed
// without its equations:
//  - with gravity negligible and no thrust, the servicer moves on a straight line in the
//    inertial frame, whatever the target's tumbling (ρ_i = C_it ρ_t linear in t): this checks
//    the Coriolis, centripetal and Euler terms of (155) at once;
//  - the torque-free target keeps its kinetic energy and angular-momentum magnitude.
#include <gtest/gtest.h>

#include "hinf/sim/hold_truth.hpp"

namespace {

hinf::sim::HoldScenario tumbling() {
  hinf::sim::HoldScenario s;
  s.initial_rate = Eigen::Vector3d(0.02, -0.03, 0.05);  // rad/s: a fast tumble
  s.initial_velocity = Eigen::Vector3d(0.01, 0.02, -0.005);
  return s;
}

TEST(HoldTruth, FreeMotionIsAStraightLineInInertialSpace) {
  hinf::sim::HoldScenario s = tumbling();
  s.mu = 1e-6;  // tidal acceleration n² ρ ~ 1e-18 m/s²
  s.orbit_rate = 1e-9;
  const hinf::sim::HoldTruth truth(s);
  hinf::sim::HoldTruthVector y = truth.initial_state(s);
  const auto inertial = [](const hinf::sim::HoldTruthVector& v) {
    const Eigen::Quaterniond q(v(6), v(7), v(8), v(9));
    return Eigen::Vector3d(q.toRotationMatrix() * v.segment<3>(0));
  };
  const Eigen::Vector3d r0 = inertial(y);
  // ρ̇_i = C_it (ρ̇_t + ω × ρ_t)
  const Eigen::Quaterniond q0(y(6), y(7), y(8), y(9));
  const Eigen::Vector3d v0 = q0.toRotationMatrix() * (y.segment<3>(3) + y.segment<3>(10).cross(y.segment<3>(0)));
  const double h = 0.01;
  for (int k = 1; k <= 20000; ++k) {  // 200 s, several turns of the target
    truth.step(y, (k - 1) * h, Eigen::Vector3d::Zero(), h);
    if (k % 5000 == 0) {
      const Eigen::Vector3d expected = r0 + v0 * (k * h);
      EXPECT_LE((inertial(y) - expected).norm(), 1e-9) << "t = " << k * h;
    }
  }
}

TEST(HoldTruth, TargetKeepsEnergyAndMomentum) {
  const hinf::sim::HoldScenario s = tumbling();
  const hinf::sim::HoldTruth truth(s);
  hinf::sim::HoldTruthVector y = truth.initial_state(s);
  const Eigen::Vector3d J = s.inertia;
  const auto energy = [&](const Eigen::Vector3d& w) { return 0.5 * w.dot(J.cwiseProduct(w)); };
  const auto momentum = [&](const Eigen::Vector3d& w) { return J.cwiseProduct(w).norm(); };
  const double E0 = energy(y.segment<3>(10)), H0 = momentum(y.segment<3>(10));
  for (int k = 0; k < 100000; ++k) truth.step(y, k * 1e-3, Eigen::Vector3d::Zero(), 1e-3);
  EXPECT_LE(std::abs(energy(y.segment<3>(10)) - E0), 1e-12 * E0);
  EXPECT_LE(std::abs(momentum(y.segment<3>(10)) - H0), 1e-12 * H0);
  EXPECT_GT((y.segment<3>(10) - s.initial_rate).norm(), 1e-3);  // it did tumble
}

// A constant thrust on a servicer at rest beside a target that does not turn: ρ = ρ0 + F t²/(2m).
TEST(HoldTruth, ThrustAcceleratesAsNewtonSays) {
  hinf::sim::HoldScenario s;
  s.initial_rate.setZero();
  s.mu = 1e-6;
  s.orbit_rate = 1e-9;
  const hinf::sim::HoldTruth truth(s);
  hinf::sim::HoldTruthVector y = truth.initial_state(s);
  const Eigen::Vector3d rho0 = y.segment<3>(0), F(5, -5, 0);
  for (int k = 0; k < 1000; ++k) truth.step(y, k * 1e-3, F, 1e-3);
  EXPECT_LE((y.segment<3>(0) - (rho0 + F / s.servicer_mass * 0.5)).norm(), 1e-14);
}

}  // namespace
