// Rotations (models/attitude.hpp, docs/maths.md §29.1) against independent constructions:
// Eigen's axis-angle rotations, DCM products, finite differences.
#include <gtest/gtest.h>

#include <random>

#include "hinf/models/attitude.hpp"

using namespace hinf::models;

namespace {
Eigen::Vector3d random_mrp(std::mt19937& g, double max_norm) {
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> u(0.0, max_norm);
  return Eigen::Vector3d(nd(g), nd(g), nd(g)).normalized() * u(g);
}
// The passive DCM of a rotation by `angle` about the unit `axis`: the transpose of Eigen's
// (active) rotation matrix.
Eigen::Matrix3d passive(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix().transpose();
}
}  // namespace

TEST(Attitude, MrpToDcmIsTheRotationByFourArctanOfTheNorm) {
  std::mt19937 g(1);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d s = random_mrp(g, 1.0);
    const Eigen::Matrix3d R = mrp_to_dcm(s);
    EXPECT_LE((R - passive(4 * std::atan(s.norm()), s)).cwiseAbs().maxCoeff(), 1e-14) << i;
    EXPECT_LE((R * R.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
  }
}

TEST(Attitude, CompositionIsTheDcmProduct) {
  std::mt19937 g(2);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d a = random_mrp(g, 1.0), b = random_mrp(g, 1.0);
    const Eigen::Matrix3d R = mrp_to_dcm(mrp_compose(a, b));
    EXPECT_LE((R - mrp_to_dcm(a) * mrp_to_dcm(b)).cwiseAbs().maxCoeff(), 1e-14) << i;
  }
}

TEST(Attitude, ShadowSetHasTheSameDcmAndItsJacobianMatchesFiniteDifferences) {
  std::mt19937 g(3);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d s = random_mrp(g, 1.5) + Eigen::Vector3d(0.05, 0, 0);
    EXPECT_LE((mrp_to_dcm(mrp_shadow(s)) - mrp_to_dcm(s)).cwiseAbs().maxCoeff(), 1e-14);
    Eigen::Matrix3d fd;
    const double h = 1e-6;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(k);
      fd.col(k) = (mrp_shadow(s + e) - mrp_shadow(s - e)) / (2 * h);
    }
    const Eigen::Matrix3d J = mrp_shadow_jacobian(s);
    EXPECT_LE((fd - J).norm(), 1e-6 * J.norm()) << i;
  }
  EXPECT_LE(mrp_canonical(Eigen::Vector3d(2, 0, 0)).norm(), 1.0);
  EXPECT_EQ(mrp_canonical(Eigen::Vector3d(0.5, 0, 0)), Eigen::Vector3d(0.5, 0, 0));
}

TEST(Attitude, KinematicsMatchTheDcmRate) {
  // Ṙ(σ) = −[ω×] R(σ) with σ̇ = M(σ) ω, by central differences of R(σ + σ̇ t).
  std::mt19937 g(4);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d s = random_mrp(g, 1.0), w = random_mrp(g, 1.0);
    const Eigen::Vector3d s_dot = mrp_kinematics(s) * w;
    const double h = 1e-6;
    const Eigen::Matrix3d R_dot = (mrp_to_dcm(s + h * s_dot) - mrp_to_dcm(s - h * s_dot)) / (2 * h);
    EXPECT_LE((R_dot + cross_matrix(w) * mrp_to_dcm(s)).norm(), 1e-8) << i;
  }
  EXPECT_LE((mrp_kinematics(Eigen::Vector3d::Zero()) - 0.25 * Eigen::Matrix3d::Identity()).norm(), 0.0);
}

TEST(Attitude, SmallErrorIsFourTimesTheAngle) {
  // R(Δσ) = I − 4[Δσ×] + 8[Δσ×]² + O(|Δσ|³): one MRP unit of error is 4 rad.
  for (double scale : {1e-3, 1e-5, 1e-7}) {
    const Eigen::Vector3d d = scale * Eigen::Vector3d(1, -2, 3);
    const Eigen::Matrix3d first = Eigen::Matrix3d::Identity() - 4 * cross_matrix(d);
    const Eigen::Matrix3d second = first + 8 * cross_matrix(d) * cross_matrix(d);
    EXPECT_LE((mrp_to_dcm(d) - first).norm(), 8 * std::sqrt(2.0) * d.squaredNorm() * (1 + 1e-6)) << scale;  // ‖8[d×]²‖_F = 8√2|d|²
    EXPECT_LE((mrp_to_dcm(d) - second).norm(), 20 * std::pow(d.norm(), 3) + 1e-15) << scale;
  }
}

TEST(Attitude, MrpFromDcmInvertsMrpToDcm) {
  std::mt19937 g(5);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d s = random_mrp(g, 1.0);
    EXPECT_LE((mrp_from_dcm(mrp_to_dcm(s)) - s).norm(), 1e-13) << i;
  }
  // near 180°: either set of the same rotation
  const Eigen::Vector3d s(0.999999, 0, 0);
  EXPECT_LE((mrp_to_dcm(mrp_from_dcm(mrp_to_dcm(s))) - mrp_to_dcm(s)).norm(), 1e-12);
}

TEST(Attitude, Euler312RoundTripAndTheFlyAroundsInitialAttitude) {
  std::mt19937 g(6);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d a(u(g), u(g), 2 * u(g));
    EXPECT_LE((euler312_from_dcm(dcm_from_euler312(a)) - a).norm(), 1e-12) << i;
  }
  // R2(θ) R1(φ) R3(ψ) as the product of Eigen's rotations about the axes
  const Eigen::Vector3d a(0.1, -0.2, 0.3);
  const Eigen::Matrix3d R = passive(a(1), Eigen::Vector3d::UnitY()) * passive(a(0), Eigen::Vector3d::UnitX()) *
                            passive(a(2), Eigen::Vector3d::UnitZ());
  EXPECT_LE((dcm_from_euler312(a) - R).norm(), 1e-15);
  // roll 2°, pitch 3°, yaw 5° → σ = (0.008150, 0.013464, 0.022043) (docs/maths.md §29.7)
  const Eigen::Vector3d s = mrp_from_dcm(dcm_from_euler312(Eigen::Vector3d(2, 3, 5) * kRadiansPerDegree));
  EXPECT_NEAR(s(0), 0.008150, 5e-7);
  EXPECT_NEAR(s(1), 0.013464, 5e-7);
  EXPECT_NEAR(s(2), 0.022043, 5e-7);
}
