// Rekf (docs/maths.md §13): reduces to the Joseph-form EKF for A_k = C_k = L = 0; matches the
// formulas docs/maths.md (95)–(98) evaluated with explicit inverses; reports the gamma condition.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hinf/runtime/ekf.hpp"
#include "hinf/models/cartesian_position.hpp"
#include "hinf/models/hill.hpp"
#include "hinf/runtime/rekf.hpp"
#include "kalman_test_values.hpp"

using namespace hinf::runtime;
using hinf::test::paper_Q;
using hinf::test::rel;
using hinf::models::CartesianPosition;
using hinf::models::HillModel;

namespace {
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;
Vec6 gauss6(std::mt19937& g) {
  std::normal_distribution<double> nd;
  Vec6 v;
  for (int i = 0; i < 6; ++i) v(i) = nd(g);
  return v;
}
HillModel::Gain paper_K() {
  HillModel::Gain K;
  K << -2.2541, -0.0071, -0.0072, -22.3975, 2.3256, 1.9369, -0.0104, -2.2493, -0.0055, 2.3259, -23.7456, 1.4544,
      -0.0072, -0.0055, -2.2471, 1.9357, 1.4552, -24.2818;
  return K;
}
}  // namespace

TEST(Rekf, ZeroUncertaintyEqualsJosephEkf) {
  std::mt19937 g(123);
  const HillModel hill(7.2722e-5, 1000.0, 0.1, paper_K());
  const Eigen::Matrix3d R = 0.01 * Eigen::Matrix3d::Identity();
  Ekf<HillModel, CartesianPosition> ekf(hill, CartesianPosition{}, paper_Q(), R);
  Rekf<HillModel, CartesianPosition> rekf(hill, CartesianPosition{}, paper_Q(), R, 0.7, Mat6::Zero(),
                                          Eigen::Matrix3d::Zero(), Mat6::Zero());
  Vec6 x0;
  x0 << 630, 520, 1000, 0, 0, 0;
  const Mat6 P0 = Vec6((Vec6() << 900, 900, 1600, 0.01, 0.01, 0.01).finished()).asDiagonal();
  ekf.init(x0, P0);
  rekf.init(x0, P0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 400; ++k) {
    const Eigen::Vector3d thrust(u(g), u(g), u(g));
    const Eigen::Vector3d y = Eigen::Vector3d(600, 550, 1040) + 5.0 * gauss6(g).head<3>();
    ASSERT_EQ(ekf.predict(thrust), FilterStatus::Ok);
    ASSERT_EQ(rekf.predict(thrust), RekfStatus::Ok);
    ASSERT_LE(rel(rekf.P(), ekf.P()), 1e-13) << k;
    ASSERT_EQ(ekf.update(y), FilterStatus::Ok);
    ASSERT_EQ(rekf.update(y), RekfStatus::Ok);
    ASSERT_LE(rel(rekf.x(), ekf.x()), 1e-13) << k;
    ASSERT_LE(rel(rekf.P(), ekf.P()), 1e-13) << k;
    ASSERT_LE(rel(rekf.K(), ekf.K()), 1e-13) << k;
  }
}

TEST(Rekf, MatchesSpecFormulasWithExplicitInverses) {
  std::mt19937 g(321);
  const HillModel hill(1.1e-3, 1000.0, 1.0, hinf::models::Discretisation::ZeroOrderHold);
  const Mat6 F = hill.A();
  const auto H = CartesianPosition{}.C();
  const Eigen::Matrix3d R = 0.04 * Eigen::Matrix3d::Identity();
  const Mat6 Q = paper_Q();
  const double gamma = 3.0;
  Mat6 A_k = Mat6::Zero();
  A_k.diagonal() << 0.02, 0.02, 0.02, 1e-3, 1e-3, 1e-3;
  const Eigen::Matrix3d C_k = 0.05 * Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 3, 6> L = Eigen::Matrix<double, 3, 6>::Zero();
  L.leftCols<3>() = 0.2 * Eigen::Matrix3d::Identity();
  Rekf<HillModel, CartesianPosition, 3> rekf(hill, CartesianPosition{}, Q, R, gamma, A_k, C_k, L);
  Vec6 x;
  x << 100, -50, 20, 0.1, 0, -0.05;
  const Mat6 P0 = 4.0 * Mat6::Identity();
  rekf.init(x, P0);
  Mat6 P = P0;
  const double g2 = gamma * gamma;
  auto M = [&](const Mat6& P_) { return Mat6((P_.inverse() - L.transpose() * L / g2).inverse()); };
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector3d u = 0.1 * gauss6(g).head<3>();
    const Eigen::Vector3d y = x.head<3>() + gauss6(g).head<3>();
    // docs/maths.md (96)
    x = F * x + hill.G() * u;
    P = F * M(P) * F.transpose() + g2 * A_k * A_k.transpose() + Q;
    ASSERT_EQ(rekf.predict(u), RekfStatus::Ok);
    ASSERT_LE(rel(rekf.P(), P), 1e-10) << k;
    // docs/maths.md (97), (98)
    const Mat6 Mp = M(P);
    const Eigen::Matrix3d Rb = g2 * C_k * C_k.transpose() + R;
    const Eigen::Matrix<double, 6, 3> K = Mp * H.transpose() * (H * Mp * H.transpose() + Rb).inverse();
    const Mat6 IKH = Mat6::Identity() - K * H;
    x = x + K * (y - H * x);
    P = IKH * Mp * IKH.transpose() + K * Rb * K.transpose();
    ASSERT_EQ(rekf.update(y), RekfStatus::Ok);
    ASSERT_LE(rel(rekf.x(), x), 1e-10) << k;
    ASSERT_LE(rel(rekf.P(), P), 1e-10) << k;
    ASSERT_LE(rel(rekf.M(), Mp), 1e-10) << k;
    // the robust filter is more conservative than the nominal one: M(P) >= P
    ASSERT_GE(Eigen::SelfAdjointEigenSolver<Mat6>(rekf.M() - Mp + Mp - P).eigenvalues().minCoeff(), -1e-12) << k;
  }
}

TEST(Rekf, GammaConditionViolationIsReportedWithSmallestEigenvalue) {
  const HillModel hill(7.2722e-5, 1000.0, 0.1);
  // L = I: gamma^2 I - P has smallest eigenvalue gamma^2 - lambda_max(P).
  const double gamma = 2.0;
  Rekf<HillModel, CartesianPosition> rekf(hill, CartesianPosition{}, paper_Q(), 0.01 * Eigen::Matrix3d::Identity(), gamma,
                                          Mat6::Zero(), Eigen::Matrix3d::Zero(), Mat6::Identity());
  const Vec6 d = (Vec6() << 1, 2, 3, 0.5, 5, 0.1).finished();
  const Mat6 P0 = d.asDiagonal();
  rekf.init(Vec6::Ones(), P0);
  EXPECT_EQ(rekf.predict(Eigen::Vector3d::Zero()), RekfStatus::GammaConditionViolated);
  EXPECT_NEAR(rekf.gamma_condition_min_eigenvalue(), 4.0 - 5.0, 1e-12);
  EXPECT_EQ(rekf.x(), Vec6::Ones());
  EXPECT_EQ(rekf.P(), P0);
  EXPECT_EQ(rekf.update(Eigen::Vector3d::Zero()), RekfStatus::GammaConditionViolated);
  EXPECT_EQ(rekf.x(), Vec6::Ones());
  // Raising gamma above sqrt(lambda_max) makes the step admissible.
  rekf.set_gamma(2.5);
  EXPECT_EQ(rekf.predict(Eigen::Vector3d::Zero()), RekfStatus::Ok);
  EXPECT_GT(rekf.gamma_condition_min_eigenvalue_of(P0), 0.0);
  EXPECT_NEAR(rekf.gamma_condition_min_eigenvalue_of(P0), 6.25 - 5.0, 1e-12);
}

TEST(Rekf, InvalidConfigurationThrows) {
  const HillModel hill(7.2722e-5, 1000.0, 0.1);
  using F = Rekf<HillModel, CartesianPosition>;
  EXPECT_THROW(F(hill, CartesianPosition{}, paper_Q(), Eigen::Matrix3d::Identity(), 0.0, Mat6::Zero(),
                 Eigen::Matrix3d::Zero(), Mat6::Zero()),
               std::invalid_argument);
  Mat6 L = Mat6::Zero();
  L(0, 0) = std::nan("");
  EXPECT_THROW(F(hill, CartesianPosition{}, paper_Q(), Eigen::Matrix3d::Identity(), 1.0, Mat6::Zero(),
                 Eigen::Matrix3d::Zero(), L),
               std::invalid_argument);
}
