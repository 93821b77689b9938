// RangeAzimuthElevation (docs/maths.md (81)–(84)): hand-computed values, Jacobian against central
// finite differences, round trip with the Cartesian conversion, and the converted
// position covariance against the inverse of the measurement Jacobian.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hinf/models/range_azimuth_elevation.hpp"

using hinf::models::RangeAzimuthElevation;
using RaeState = RangeAzimuthElevation::State;
using Vec = RangeAzimuthElevation::Vector;

namespace {
RaeState pos(double x, double y, double z) { return (RaeState() << x, y, z, 0.1, -0.2, 0.3).finished(); }

Eigen::Matrix3d rotation(double yaw, double pitch, double roll) {
  return (Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}
}  // namespace

TEST(RangeAzimuthElevation, HandComputedValues) {
  const RangeAzimuthElevation m;
  Vec y = m.h(pos(3, 4, 0));
  EXPECT_NEAR(y(0), 5.0, 1e-15);
  EXPECT_NEAR(y(1), std::atan(4.0 / 3.0), 1e-15);
  EXPECT_NEAR(y(2), 0.0, 1e-15);
  // p = (1, 1, -sqrt 2): rho = 2, alpha = pi/4, beta = pi/4 (p_z = -rho sin beta).
  y = m.h(pos(1, 1, -std::sqrt(2.0)));
  EXPECT_NEAR(y(0), 2.0, 1e-15);
  EXPECT_NEAR(y(1), M_PI / 4, 1e-15);
  EXPECT_NEAR(y(2), M_PI / 4, 1e-15);
  y = m.h(pos(-1, 0, 1));
  EXPECT_NEAR(y(1), M_PI, 1e-15);
  EXPECT_NEAR(y(2), -M_PI / 4, 1e-15);
  // Body frame rotated by 90 deg about z (C_bl = R_z(-90 deg) maps frame x to body -y).
  const Eigen::Matrix3d C_bl = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const RangeAzimuthElevation mb(C_bl);
  y = mb.h(pos(2, 0, 0));
  EXPECT_NEAR(y(0), 2.0, 1e-15);
  EXPECT_NEAR(y(1), -M_PI / 2, 1e-15);
}

TEST(RangeAzimuthElevation, JacobianMatchesCentralDifferences) {
  std::mt19937 g(42);
  std::uniform_real_distribution<double> u(-1000, 1000), ang(-M_PI, M_PI);
  for (int trial = 0; trial < 50; ++trial) {
    const RangeAzimuthElevation m(rotation(ang(g), 0.5 * ang(g), ang(g)));
    const RaeState x = pos(u(g), u(g), u(g));
    const auto H = m.H(x);
    const double h = 1e-4;
    for (int j = 0; j < 6; ++j) {
      RaeState e = RaeState::Zero();
      e(j) = h;
      Vec d = m.residual(m.h(x + e), m.h(x - e)) / (2 * h);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(H(i, j), d(i), 1e-8 * (1.0 + std::abs(d(i)))) << "trial " << trial << " (" << i << "," << j << ")";
    }
  }
}

TEST(RangeAzimuthElevation, CartesianConversionInvertsH) {
  std::mt19937 g(43);
  std::uniform_real_distribution<double> u(-1000, 1000), ang(-M_PI, M_PI);
  for (int trial = 0; trial < 100; ++trial) {
    const RangeAzimuthElevation m(rotation(ang(g), 0.5 * ang(g), ang(g)));
    const RaeState x = pos(u(g), u(g), u(g));
    const Eigen::Vector3d p = m.position_from_measurement(m.h(x));
    EXPECT_LE((p - x.head<3>()).norm(), 1e-12 * x.head<3>().norm());
    // and h o conversion = identity on (rho, alpha, beta) in range
    const Vec y(std::abs(u(g)) + 1.0, ang(g), 0.49 * ang(g));
    const Vec y2 = m.h((RaeState() << m.position_from_measurement(y), 0, 0, 0).finished());
    EXPECT_LE(m.residual(y2, y).norm(), 1e-12 * (1 + y.norm()));
  }
}

TEST(RangeAzimuthElevation, ConvertedCovarianceIsInverseJacobianSandwich) {
  // The conversion is the inverse of h on position, so its Jacobian is the inverse of the
  // position block of H: Cov = Hp^-1 Sigma Hp^-T. Also: state dependent and correlated.
  const RangeAzimuthElevation m(rotation(0.3, -0.2, 0.7));
  const double s_rho = 0.1, s_a = 1e-3, s_b = 2e-3;
  const Eigen::Matrix3d Sigma = Eigen::Vector3d(s_rho * s_rho, s_a * s_a, s_b * s_b).asDiagonal();
  Eigen::Matrix3d first = Eigen::Matrix3d::Zero();
  for (const RaeState& x : {pos(600, 550, 1040), pos(-50, 20, 3)}) {
    const Vec y = m.h(x);
    const Eigen::Matrix3d Hp = m.H(x).leftCols<3>();
    const Eigen::Matrix3d Hinv = Hp.inverse();
    const Eigen::Matrix3d expect = Hinv * Sigma * Hinv.transpose();
    const Eigen::Matrix3d Cov = m.position_covariance(y, s_rho, s_a, s_b);
    EXPECT_LE((Cov - expect).norm(), 1e-10 * expect.norm());
    EXPECT_GT(std::abs(Cov(0, 1)) / std::sqrt(Cov(0, 0) * Cov(1, 1)), 1e-3);  // correlated
    if (x(0) == 600) first = Cov;
  }
  EXPECT_GT((first - m.position_covariance(m.h(pos(-50, 20, 3)), s_rho, s_a, s_b)).norm(), 1e-3 * first.norm());
  // Monte Carlo cross-check of the first-order covariance at small noise.
  std::mt19937 g(44);
  std::normal_distribution<double> nd;
  const Vec y = m.h(pos(600, 550, 1040));
  const Eigen::Vector3d p0 = m.position_from_measurement(y);
  Eigen::Matrix3d mc = Eigen::Matrix3d::Zero();
  const int N = 200000;
  for (int i = 0; i < N; ++i) {
    const Vec yn = y + Vec(s_rho * nd(g), s_a * nd(g), s_b * nd(g));
    const Eigen::Vector3d d = m.position_from_measurement(yn) - p0;
    mc += d * d.transpose();
  }
  mc /= N;
  const Eigen::Matrix3d Cov = m.position_covariance(y, s_rho, s_a, s_b);
  EXPECT_LE((mc - Cov).norm(), 0.02 * Cov.norm());  // sampling error ~ sqrt(2/N) ~ 0.3 %
}

TEST(RangeAzimuthElevation, AzimuthResidualIsWrapped) {
  const RangeAzimuthElevation m;
  const Vec r = m.residual(Vec(1, -M_PI + 0.01, 0), Vec(1, M_PI - 0.01, 0));
  EXPECT_NEAR(r(1), 0.02, 1e-14);
  EXPECT_NEAR(RangeAzimuthElevation::wrap_pi(-M_PI), M_PI, 1e-15);
}

TEST(RangeAzimuthElevation, RejectsNonRotation) {
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
  C(0, 0) = -1;  // reflection
  EXPECT_THROW(RangeAzimuthElevation{C}, std::invalid_argument);
  C = 1.01 * Eigen::Matrix3d::Identity();
  EXPECT_THROW(RangeAzimuthElevation{C}, std::invalid_argument);
}
