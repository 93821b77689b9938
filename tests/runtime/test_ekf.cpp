// Ekf against an independently written textbook Kalman filter (information form with
// explicit inverses), plus covariance-health, NIS and status-policy tests.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "hinf/runtime/ekf.hpp"
#include "hinf/models/cartesian_position.hpp"
#include "hinf/models/hill.hpp"
#include "hinf/models/linear.hpp"
#include "hinf/models/range_azimuth_elevation.hpp"
#include "kalman_test_values.hpp"

using namespace hinf::runtime;
using hinf::test::paper_Q;
using hinf::test::rel;
using hinf::models::CartesianPosition;
using hinf::models::HillModel;
using hinf::models::LinearMeasurement;
using hinf::models::LinearModel;
using hinf::models::RangeAzimuthElevation;

namespace {
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

template <int R, int C>
Eigen::Matrix<double, R, C> rnd(std::mt19937& g) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix<double, R, C> M;
  for (int j = 0; j < C; ++j)
    for (int i = 0; i < R; ++i) M(i, j) = u(g);
  return M;
}
template <int N>
Eigen::Matrix<double, N, N> rnd_spd(std::mt19937& g, double floor) {
  const auto A = rnd<N, N>(g);
  return A * A.transpose() + floor * Eigen::Matrix<double, N, N>::Identity();
}
template <int N>
Eigen::Matrix<double, N, 1> gauss(std::mt19937& g) {
  std::normal_distribution<double> nd;
  Eigen::Matrix<double, N, 1> v;
  for (int i = 0; i < N; ++i) v(i) = nd(g);
  return v;
}
}  // namespace

TEST(Ekf, LinearModelEqualsTextbookKalmanFilter) {
  std::mt19937 g(2024);
  using Model = LinearModel<6, 2>;
  using Meas = LinearMeasurement<6, 3>;
  Mat6 F = rnd<6, 6>(g);
  F *= 0.98 / F.norm() + 0.0;  // stable but not trivial
  F += 0.5 * Mat6::Identity();
  const auto G = rnd<6, 2>(g);
  const auto H = rnd<3, 6>(g);
  const Mat6 Q = rnd_spd<6>(g, 0.01);
  const Eigen::Matrix3d R = rnd_spd<3>(g, 0.1);
  const Mat6 P0 = rnd_spd<6>(g, 1.0);
  const Vec6 x0 = gauss<6>(g);

  Ekf<Model, Meas> ekf(Model(F, G), Meas(H), Q, R);
  ekf.init(x0, P0);
  // Textbook KF, information form: P+ = (P-^-1 + H^T R^-1 H)^-1, K = P+ H^T R^-1.
  Vec6 x = x0;
  Mat6 P = P0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector2d u = gauss<2>(g);
    const Eigen::Vector3d y = gauss<3>(g) * 3.0;
    x = F * x + G * u;
    P = F * P * F.transpose() + Q;
    ASSERT_EQ(ekf.predict(u), FilterStatus::Ok);
    ASSERT_LE(rel(ekf.x(), x), 1e-10) << "predict k = " << k;
    ASSERT_LE(rel(ekf.P(), P), 1e-10) << "predict k = " << k;
    const Mat6 Pp = (P.inverse() + H.transpose() * R.inverse() * H).inverse();
    const Eigen::Matrix<double, 6, 3> K = Pp * H.transpose() * R.inverse();
    x = x + K * (y - H * x);
    P = Pp;
    ASSERT_EQ(ekf.update(y), FilterStatus::Ok);
    ASSERT_LE(rel(ekf.x(), x), 1e-10) << "update k = " << k;
    ASSERT_LE(rel(ekf.P(), P), 1e-10) << "update k = " << k;
    ASSERT_LE(rel(ekf.K(), K), 1e-10) << "update k = " << k;
  }
}

TEST(Ekf, ConvergedCovarianceSolvesTheRiccatiEquation) {
  // Fixed point of predict+update: P = F (P - P H^T (H P H^T + R)^-1 H P) F^T + Q,
  // checked by its residual (explicit inverse, test only).
  std::mt19937 g(5);
  using Model = LinearModel<6, 1>;
  using Meas = LinearMeasurement<6, 3>;
  Mat6 F = rnd<6, 6>(g);
  F *= 0.9 / F.norm();
  const auto H = rnd<3, 6>(g);
  const Mat6 Q = rnd_spd<6>(g, 0.1);
  const Eigen::Matrix3d R = rnd_spd<3>(g, 0.1);
  Ekf<Model, Meas> ekf(Model(F, Eigen::Matrix<double, 6, 1>::Zero()), Meas(H), Q, R);
  ekf.init(Vec6::Zero(), 1e3 * Mat6::Identity());
  for (int k = 0; k < 500; ++k) {
    ekf.update(Eigen::Vector3d::Zero());
    ekf.predict(Eigen::Matrix<double, 1, 1>::Zero());
  }
  const Mat6 P = ekf.P();
  const Mat6 rhs = F * (P - P * H.transpose() * (H * P * H.transpose() + R).inverse() * H * P) * F.transpose() + Q;
  EXPECT_LE(rel(P, rhs), 1e-12);
}

TEST(Ekf, CovarianceStaysSymmetricPositiveDefiniteOverLongRuns) {
  // Hill model with orbit control, paper noise levels, 20 000 steps (2000 s), and an
  // ill-conditioned start (P0 = 1e8 I against R = 1e-8 I).
  std::mt19937 g(9);
  HillModel::Gain K;
  K << -2.2541, -0.0071, -0.0072, -22.3975, 2.3256, 1.9369, -0.0104, -2.2493, -0.0055, 2.3259, -23.7456, 1.4544,
      -0.0072, -0.0055, -2.2471, 1.9357, 1.4552, -24.2818;
  const HillModel hill(7.2722e-5, 1000.0, 0.1, K);
  for (double r : {0.01, 1e-8}) {
    Ekf<HillModel, CartesianPosition> ekf(hill, CartesianPosition{}, paper_Q(), r * Eigen::Matrix3d::Identity());
    ekf.init(Vec6::Zero(), (r < 1e-6 ? 1e8 : 100.0) * Mat6::Identity());
    for (int k = 0; k < 20000; ++k) {
      ASSERT_EQ(ekf.predict(Eigen::Vector3d::Zero()), FilterStatus::Ok) << k;
      ASSERT_EQ(ekf.update(gauss<3>(g)), FilterStatus::Ok) << k;
      const Mat6& P = ekf.P();
      ASSERT_EQ((P - P.transpose()).cwiseAbs().maxCoeff(), 0.0) << k;  // exactly symmetric
      if (k % 50 == 0) {
        // Cholesky succeeds, and no eigenvalue is below the round-off level of an
        // eigen-solver (absolute accuracy ~ eps |P|, which cannot resolve the 1e-8 m^2
        // position variances next to 1e8 velocity variances at the start of the
        // ill-conditioned run).
        ASSERT_EQ(Eigen::LLT<Mat6>(P).info(), Eigen::Success) << k;
        Eigen::SelfAdjointEigenSolver<Mat6> es(P);
        ASSERT_GT(es.eigenvalues().minCoeff(), -1e-14 * P.norm()) << k;
      }
    }
    // Converged: strictly positive definite.
    Eigen::SelfAdjointEigenSolver<Mat6> es(ekf.P());
    EXPECT_GT(es.eigenvalues().minCoeff(), 0.0) << "R = " << r;
  }
}

TEST(Ekf, NisIsChiSquareOnAConsistentLinearProblem) {
  // Truth simulated with the filter's own Q and R: NIS ~ chi^2(3), mean 3.
  std::mt19937 g(77);
  const double T = 1.0;
  const HillModel hill(1.1e-3, 1000.0, T, hinf::models::Discretisation::ZeroOrderHold);
  const Mat6 Q = 1e-4 * Mat6::Identity();
  const Eigen::Matrix3d R = 0.25 * Eigen::Matrix3d::Identity();
  const Eigen::LLT<Mat6> Qc(Q);
  Ekf<HillModel, CartesianPosition> ekf(hill, CartesianPosition{}, Q, R);
  Vec6 x;
  x << 100, -50, 20, 0.1, 0.0, -0.05;
  const Mat6 P0 = 10.0 * Mat6::Identity();
  ekf.init(x + Eigen::LLT<Mat6>(P0).matrixL().toDenseMatrix() * gauss<6>(g), P0);
  double sum = 0;
  const int N = 5000;
  for (int k = 0; k < N; ++k) {
    x = hill.f(x, Eigen::Vector3d::Zero()) + Qc.matrixL().toDenseMatrix() * gauss<6>(g);
    const Eigen::Vector3d y = x.head<3>() + 0.5 * gauss<3>(g);
    ASSERT_EQ(ekf.predict(Eigen::Vector3d::Zero()), FilterStatus::Ok);
    ASSERT_EQ(ekf.update(y), FilterStatus::Ok);
    // nis() against an explicit-inverse evaluation
    const Eigen::Vector3d nu = ekf.innovation();
    ASSERT_NEAR(ekf.nis(), nu.dot(ekf.S().inverse() * nu), 1e-9 * (1 + ekf.nis()));
    sum += ekf.nis();
  }
  EXPECT_NEAR(sum / N, 3.0, 0.15);  // std of the mean: sqrt(6/N) = 0.035
}

TEST(Ekf, RangeAzimuthElevationTracksTruth) {
  std::mt19937 g(31);
  const HillModel hill(7.2722e-5, 1000.0, 1.0, hinf::models::Discretisation::ZeroOrderHold);
  const RangeAzimuthElevation rae;
  const Eigen::Vector3d sig(0.1, 1e-4, 1e-4);
  Ekf<HillModel, RangeAzimuthElevation> ekf(hill, rae, 1e-10 * Mat6::Identity(),
                                            Eigen::Vector3d(sig.array().square()).asDiagonal());
  Vec6 x;
  x << 600, 550, 1040, 0.02, -0.08, 0.03;
  Vec6 x0;
  x0 << 630, 520, 1000, 0, 0, 0;
  ekf.init(x0, Eigen::Matrix<double, 6, 1>((Vec6() << 1e3, 1e3, 1e3, 1, 1, 1).finished()).asDiagonal());
  for (int k = 0; k < 1000; ++k) {
    x = hill.f(x, Eigen::Vector3d::Zero());
    ASSERT_EQ(ekf.predict(Eigen::Vector3d::Zero()), FilterStatus::Ok);
    const Eigen::Vector3d y = rae.h(x) + Eigen::Vector3d(sig.array() * gauss<3>(g).array());
    ASSERT_EQ(ekf.update(y), FilterStatus::Ok);
  }
  EXPECT_LT((ekf.x().head<3>() - x.head<3>()).norm(), 0.5);
  EXPECT_LT((ekf.x().tail<3>() - x.tail<3>()).norm(), 0.01);
}

TEST(EkfPolicy, NonFiniteInputsSkipTheStep) {
  const HillModel hill(7.2722e-5, 1000.0, 0.1);
  Ekf<HillModel, CartesianPosition> ekf(hill, CartesianPosition{}, paper_Q(), 0.01 * Eigen::Matrix3d::Identity());
  ekf.init(Vec6::Ones(), Mat6::Identity());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ekf.predict(Eigen::Vector3d(nan, 0, 0)), FilterStatus::NonFiniteInput);
  EXPECT_EQ(ekf.update(Eigen::Vector3d(0, std::numeric_limits<double>::infinity(), 0)), FilterStatus::NonFiniteInput);
  EXPECT_EQ(ekf.x(), Vec6::Ones());
  EXPECT_EQ(ekf.P(), Mat6::Identity());
}

TEST(EkfPolicy, ModelSingularityIsReported) {
  // Range/azimuth/elevation at zero range: h undefined.
  const HillModel hill(7.2722e-5, 1000.0, 0.1);
  Ekf<HillModel, RangeAzimuthElevation> ekf(hill, RangeAzimuthElevation{}, paper_Q(), 0.01 * Eigen::Matrix3d::Identity());
  ekf.init(Vec6::Zero(), Mat6::Identity());
  EXPECT_EQ(ekf.update(Eigen::Vector3d(1, 0, 0)), FilterStatus::ModelNotFinite);
  EXPECT_EQ(ekf.x(), Vec6::Zero());
}

TEST(EkfPolicy, InnovationGateRejectsOutliers) {
  const HillModel hill(7.2722e-5, 1000.0, 0.1);
  Ekf<HillModel, CartesianPosition> ekf(hill, CartesianPosition{}, paper_Q(), 0.01 * Eigen::Matrix3d::Identity());
  ekf.init(Vec6::Zero(), 0.01 * Mat6::Identity());
  ekf.set_innovation_gate(16.27);  // chi^2(3) 0.999 quantile
  // S = P_pos + R = 0.02 I after no predict: y = (1, 0, 0) gives NIS = 1 / 0.02 = 50.
  EXPECT_EQ(ekf.update(Eigen::Vector3d(1, 0, 0)), FilterStatus::InnovationRejected);
  EXPECT_NEAR(ekf.nis(), 50.0, 1e-12);
  EXPECT_EQ(ekf.x(), Vec6::Zero());
  EXPECT_EQ(ekf.P(), 0.01 * Mat6::Identity());
  EXPECT_EQ(ekf.update(Eigen::Vector3d(0.1, 0, 0)), FilterStatus::Ok);  // NIS 0.5
  EXPECT_NEAR(ekf.nis(), 0.5, 1e-12);
}

TEST(EkfPolicy, LossOfPositiveDefinitenessIsReportedOrReset) {
  const HillModel hill(7.2722e-5, 1000.0, 0.1);
  Mat6 bad = Mat6::Identity();
  bad(2, 2) = -1.0;  // indefinite
  const Mat6 P0 = 4.0 * Mat6::Identity();
  Ekf<HillModel, CartesianPosition> ekf(hill, CartesianPosition{}, Mat6::Zero(), 0.01 * Eigen::Matrix3d::Identity());
  ekf.init(Vec6::Zero(), P0);
  ekf.set_state(Vec6::Ones(), bad);
  EXPECT_EQ(ekf.predict(Eigen::Vector3d::Zero()), FilterStatus::CovarianceNotPD);
  EXPECT_FALSE(Eigen::LLT<Mat6>(ekf.P()).info() == Eigen::Success);

  ekf.set_covariance_policy(CovariancePolicy::ResetToP0);
  ekf.set_state(Vec6::Ones(), bad);
  EXPECT_EQ(ekf.predict(Eigen::Vector3d::Zero()), FilterStatus::CovarianceReset);
  EXPECT_EQ(ekf.P(), P0);
  EXPECT_EQ(ekf.x(), hill.f(Vec6::Ones(), Eigen::Vector3d::Zero()));  // x kept

  // Innovation covariance not PD: S = H P H^T + R with P(2,2) = -1 -> S(2,2) < 0.
  ekf.set_state(Vec6::Ones(), bad);
  EXPECT_EQ(ekf.update(Eigen::Vector3d::Zero()), FilterStatus::InnovationCovarianceNotPD);
  EXPECT_EQ(ekf.x(), Vec6::Ones());
}

TEST(EkfPolicy, InvalidConfigurationThrows) {
  const HillModel hill(7.2722e-5, 1000.0, 0.1);
  Mat6 Q = paper_Q();
  Q(0, 1) = 1e-3;  // not symmetric
  EXPECT_THROW((Ekf<HillModel, CartesianPosition>(hill, CartesianPosition{}, Q, Eigen::Matrix3d::Identity())),
               std::invalid_argument);
  EXPECT_THROW((Ekf<HillModel, CartesianPosition>(hill, CartesianPosition{}, -paper_Q(), Eigen::Matrix3d::Identity())),
               std::invalid_argument);
  EXPECT_THROW((Ekf<HillModel, CartesianPosition>(hill, CartesianPosition{}, paper_Q(), Eigen::Matrix3d::Zero())),
               std::invalid_argument);
  Ekf<HillModel, CartesianPosition> ekf(hill, CartesianPosition{}, paper_Q(), Eigen::Matrix3d::Identity());
  EXPECT_THROW(ekf.init(Vec6::Zero(), -Mat6::Identity()), std::invalid_argument);
}
