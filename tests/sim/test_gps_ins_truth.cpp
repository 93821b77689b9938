// The gps_ins_relative truth (sim/gps_ins_truth.hpp, docs/maths.md §30) against closed forms
// and the filter model: the CW fly-around circle, the nonlinear drift, the rate equation
// (189) along the truth, the PD law, the GPS geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "hinf/sim/gps_ins_truth.hpp"

using namespace hinf::sim;
namespace ix = hinf::models::gps_ins_index;

namespace {
GpsInsScenario exact_circle() {
  GpsInsScenario s;
  s.initial_position = {100.0, 0.0, -100.0 * std::sqrt(3.0)};  // |ρ| = 200 m exactly
  return s;
}
}  // namespace

// C4: drift-free, CW truth: |ρ| stays at 200 m within 1 mm over 10 000 s; the nonlinear
// truth stays within 1 m of it.
TEST(GpsInsTruth, DriftFreeCircleKeepsItsRadius) {
  GpsInsScenario s = exact_circle();
  s.truth_dynamics = GpsInsTruthDynamics::Cw;
  const GpsInsTruth cw(s);
  s.truth_dynamics = GpsInsTruthDynamics::Nonlinear;
  const GpsInsTruth nonlinear(s);
  GpsInsTruthState a = cw.initial_state(), b = nonlinear.initial_state();
  Rng rng(1);
  double worst_radius = 0, worst_gap = 0;
  for (int k = 0; k < 10000; ++k) {
    cw.step(a, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), rng);
    nonlinear.step(b, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), rng);
    worst_radius = std::max(worst_radius, std::abs(a.translation.head<3>().norm() - 200.0));
    worst_gap = std::max(worst_gap, (a.translation.head<3>() - b.translation.head<3>()).norm());
  }
  EXPECT_LE(worst_radius, 1e-3);
  EXPECT_LE(worst_gap, 1.0);
  EXPECT_GT(worst_gap, 1e-4);  // the nonlinear truth is not the CW one
  // drift-free means ẏ(0) = −2 n x(0) = −0.22031 m/s
  EXPECT_NEAR(s.initial_velocity_used().y(), -0.22031, 1e-5);
}

// C3: ω̇ of the filter model (189) is the derivative of the truth's ω = ω_BI − Ω − ν.
TEST(GpsInsTruth, RateEquationMatchesTheTruth) {
  GpsInsScenario s = exact_circle();
  s.sample_time = 1e-3;
  s.truth_substeps = 1;
  s.initial_rate = Eigen::Vector3d(1e-3, -2e-3, 5e-4);
  const GpsInsTruth truth(s);
  hinf::models::GpsInsProcess model(s.model_parameters(hinf::models::GpsInsJacobian::Full));
  Rng rng(2);
  GpsInsTruthState y = truth.initial_state();
  for (int i = 0; i < 5; ++i) {
    const double t = 0.5 * i, h = s.sample_time;
    const Eigen::Vector3d T = truth.control_torque(y, t);
    // the truth two steps ahead with the torque held; the three-point difference is O(h²)
    GpsInsTruthState y1 = y, y2;
    truth.step(y1, T, Eigen::Vector3d::Zero(), rng);
    y2 = y1;
    truth.step(y2, T, Eigen::Vector3d::Zero(), rng);
    auto rate = [&](const GpsInsTruthState& state, double at) {
      return Eigen::Vector3d(truth.relative_state(state, at).segment<3>(ix::kRate));
    };
    const Eigen::Vector3d w_dot_fd = (-3 * rate(y, t) + 4 * rate(y1, t + h) - rate(y2, t + 2 * h)) / (2 * h);
    model.set_epoch(truth.epoch(t));
    const Eigen::Vector3d w_dot = model.rate_derivative(truth.relative_state(y, t), T);
    EXPECT_LE((w_dot - w_dot_fd).norm(), 1e-7 * w_dot.norm()) << i;
    y = y1;
  }
}

// The PD law takes the 6° initial attitude error to its steady state (no disturbance): F turns
// about z_F, which is not the orbit normal, so ω_BI = Ω + ν changes direction at the rate n and
// the law, without that angular acceleration in its feed-forward, lags by T/k_p ≈ J n²/k_p ≈
// 5e-4 (MRP) at steady state.
TEST(GpsInsTruth, AttitudeControlHoldsTheFlyAroundFrame) {
  GpsInsScenario s;
  const GpsInsTruth truth(s);
  Rng rng(3);
  GpsInsTruthState y = truth.initial_state();
  const auto x0 = truth.relative_state(y, 0);
  EXPECT_LE((x0.segment<3>(ix::kAttitude) - Eigen::Vector3d(0.008150, 0.013464, 0.022043)).norm(), 1e-6);
  EXPECT_LE(x0.segment<3>(ix::kRate).norm(), 1e-15);
  for (int k = 0; k < 2000; ++k) {
    const double t = k * s.sample_time;
    truth.step(y, truth.control_torque(y, t), Eigen::Vector3d::Zero(), rng);
  }
  const auto x = truth.relative_state(y, 2000);
  EXPECT_LE(x.segment<3>(ix::kAttitude).norm(), 1e-3);
  EXPECT_LE(x.segment<3>(ix::kRate).norm(), 1e-5);
}

// The LVLH-fixed constellation: PDOP 1.53 (no clock column: the clock difference is known),
// √(1/1.75 + 2/1.125) in closed form; every satellite 2e7 m from the target.
TEST(GpsInsTruth, ConstellationGeometry) {
  const GpsInsScenario s;
  Eigen::Matrix3d G_t_G = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& d : s.satellite_offsets()) {
    EXPECT_NEAR(d.norm(), 2.0e7, 1e-6);
    G_t_G += d.normalized() * d.normalized().transpose();
  }
  const double pdop = std::sqrt(G_t_G.inverse().trace());
  EXPECT_NEAR(pdop, std::sqrt(1 / 1.75 + 2 / 1.125), 1e-12);
  EXPECT_NEAR(pdop, 1.53, 0.005);
  // the first satellite is at the zenith (+x of LVLH)
  EXPECT_NEAR(s.satellite_offsets()[0].normalized().x(), 1.0, 1e-15);
}

// The sensors: noise-free measurements are the model's h of the relative state; the gyro
// sees ω_BI + b.
TEST(GpsInsTruth, NoiseFreeMeasurementsAreTheModel) {
  GpsInsScenario s;
  s.gyro_noise_sigma = s.pseudorange_sigma = s.phase_sigma = 0;
  const GpsInsTruth truth(s);
  Rng rng(4);
  const GpsInsTruthState y = truth.initial_state();
  const auto z = truth.measure(y, 0, rng);
  EXPECT_LE((z.head<3>() - (y.omega_BI + y.bias)).norm(), 1e-18);
  // the pseudorange difference of the chaser at ρ: |ρ| ≪ range, so Δp ≈ −e·ρ
  const auto e = truth.epoch(0);
  const Eigen::Vector3d los = (e.r_satellite[0] - e.r_target).normalized();
  EXPECT_NEAR(z(3), -los.dot(e.R_RI.transpose() * y.translation.head<3>()), 1e-3);
}
