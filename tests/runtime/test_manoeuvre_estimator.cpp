// The transient-model manoeuvre estimator (docs/maths.md (223)–(226)): check 001-U5 (the
// innovation form of Û's covariance is [P(t+|t) − P(t+|t+)]/Δt² and the source's (7b) is no
// smaller), Û against its definition, the prediction with the chaser's control, and the
// windowed-NIS detector against its sum. The model matrices are written out here (CW), not
// taken from models/.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hinf/runtime/manoeuvre_estimator.hpp"

namespace {

using hinf::runtime::FilterStatus;
using hinf::runtime::ManoeuvreEstimatorSettings;
using hinf::runtime::TransientManoeuvreEstimator;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix63 = Eigen::Matrix<double, 6, 3>;

// The CW transition (x radial, y along-track) and a first-order white-acceleration Q_d.
struct Cw {
  double n = 1.156874e-3, dt = 1, q = 0.25;
  Matrix6 Phi() const {
    const double c = std::cos(n * dt), s = std::sin(n * dt);
    Matrix6 P;
    P << 4 - 3 * c, 0, 0, s / n, 2 * (1 - c) / n, 0, 6 * (s - n * dt), 1, 0, -2 * (1 - c) / n,
        (4 * s - 3 * n * dt) / n, 0, 0, 0, c, 0, 0, s / n, 3 * n * s, 0, 0, c, 2 * s, 0, -6 * n * (1 - c), 0, 0,
        -2 * s, 4 * c - 3, 0, 0, 0, -n * s, 0, 0, c;
    return P;
  }
  Matrix6 Qd() const {
    Matrix6 Q = Matrix6::Zero();
    Q.topLeftCorner<3, 3>() = q * dt * dt * dt / 3 * Eigen::Matrix3d::Identity();
    Q.topRightCorner<3, 3>() = Q.bottomLeftCorner<3, 3>() = q * dt * dt / 2 * Eigen::Matrix3d::Identity();
    Q.bottomRightCorner<3, 3>() = q * dt * Eigen::Matrix3d::Identity();
    return Q;
  }
  Matrix63 Gamma() const {
    Matrix63 G = Matrix63::Zero();
    G.topRows<3>() = dt * dt / 2 * Eigen::Matrix3d::Identity();
    G.bottomRows<3>() = dt * Eigen::Matrix3d::Identity();
    return G;
  }
};

Matrix6 P0() {
  Vector6 s;
  s << 1, 1, 1, 0.1, 0.1, 0.1;
  return s.cwiseAbs2().asDiagonal();
}

Eigen::Matrix3d R() {
  Eigen::Matrix3d r;
  r << 4, 1, 0.5, 1, 9, -1, 0.5, -1, 16;  // a correlated position covariance, as T_m J R Jᵀ T_mᵀ is
  return r;
}

// 001-U5, with zero manoeuvre and noisy measurements over 200 steps.
TEST(ManoeuvreEstimator, InnovationCovarianceIsTheCovarianceDropOverDt2AndPaperFormIsNoSmaller) {
  const Cw cw;
  TransientManoeuvreEstimator f;
  Vector6 x0;
  x0 << 9745.34, 58364.26, 0, 0.1514, -17.346, 0;
  f.init(x0, P0());
  std::mt19937_64 gen(7);
  std::normal_distribution<double> N(0, 1);
  Vector6 truth = x0;
  const Eigen::Matrix3d L = R().llt().matrixL();
  for (int k = 0; k < 200; ++k) {
    truth = cw.Phi() * truth;
    const Eigen::Vector3d y = truth.head<3>() + L * Eigen::Vector3d(N(gen), N(gen), N(gen));
    ASSERT_EQ(f.step(cw.Phi(), cw.Qd(), cw.Gamma(), y, R(), Eigen::Vector3d::Zero(), cw.dt), FilterStatus::Ok);
    const Eigen::Matrix3d drop = (f.P_prior() - f.P()).bottomRightCorner<3, 3>() / (cw.dt * cw.dt);
    const Eigen::Matrix3d innov = f.manoeuvre_covariance_innovation();
    EXPECT_LE((innov - drop).cwiseAbs().maxCoeff(), 1e-12 * drop.cwiseAbs().maxCoeff()) << "step " << k;
    const Eigen::Matrix3d paper = f.manoeuvre_covariance_paper();
    for (int i = 0; i < 3; ++i) EXPECT_GE(paper(i, i), innov(i, i)) << "step " << k << ", axis " << i;
    // (7b) − innovation form is PSD, not only its diagonal
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(paper - innov).eigenvalues().minCoeff(),
              -1e-12 * paper.norm());
  }
}

// Û = [(X⁺ − X⁻)/Δt]_v + U_C; with the control in the prediction, X⁻ carries −Γ U_C and Û drops
// the + U_C. A constant relative acceleration is recovered once the filter has settled.
TEST(ManoeuvreEstimator, ManoeuvreIsTheVelocityCorrectionOverDtPlusTheChaserCommand) {
  const Cw cw;
  const Eigen::Vector3d uc(0.2, -0.1, 0.05), ut(0.5, 0.5, 0);
  for (bool with_control : {false, true}) {
    ManoeuvreEstimatorSettings s;
    s.predict_with_chaser_control = with_control;
    TransientManoeuvreEstimator f(s);
    Vector6 x0 = Vector6::Zero();
    x0(1) = 50000;
    f.init(x0, P0());
    Vector6 truth = x0;
    for (int k = 0; k < 400; ++k) {
      const Vector6 before = f.x();
      truth = cw.Phi() * truth + cw.Gamma() * (ut - uc);
      ASSERT_EQ(f.step(cw.Phi(), cw.Qd(), cw.Gamma(), truth.head<3>(), R() * 1e-6, uc, cw.dt), FilterStatus::Ok);
      Vector6 prior = cw.Phi() * before;
      if (with_control) prior -= cw.Gamma() * uc;
      EXPECT_LE((f.x_prior() - prior).cwiseAbs().maxCoeff(), 1e-9 * prior.norm());
      const Eigen::Vector3d expected = (f.x() - prior).tail<3>() / cw.dt + (with_control ? Eigen::Vector3d::Zero() : uc);
      EXPECT_LE((f.manoeuvre() - expected).cwiseAbs().maxCoeff(), 1e-9) << "step " << k;
    }
    EXPECT_LE((f.manoeuvre() - ut).cwiseAbs().maxCoeff(), 2e-3) << "with_control " << with_control;
  }
}

// D_k is the sum of the last w NIS values; the alarm is D_k > threshold once the window is full.
TEST(ManoeuvreEstimator, WindowedNisDetectorSumsTheLastWindowAndAlarmsAboveTheThreshold) {
  const Cw cw;
  ManoeuvreEstimatorSettings s;
  s.nis_window = 5;
  s.nis_threshold = 40;
  TransientManoeuvreEstimator f(s);
  f.init(Vector6::Zero(), P0());
  std::vector<double> history;
  bool alarmed = false;
  for (int k = 0; k < 60; ++k) {
    // a jump of the measured position at step 30: the innovation grows, so does D_k
    const Eigen::Vector3d y = k < 30 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(30, 0, 0);
    ASSERT_EQ(f.step(cw.Phi(), cw.Qd(), cw.Gamma(), y, R(), Eigen::Vector3d::Zero(), cw.dt), FilterStatus::Ok);
    history.push_back(f.nis());
    double sum = 0;
    for (std::size_t i = history.size() > 5 ? history.size() - 5 : 0; i < history.size(); ++i) sum += history[i];
    EXPECT_NEAR(f.window_nis(), sum, 1e-12 * std::max(1.0, sum));
    EXPECT_EQ(f.window_full(), k >= 4);
    EXPECT_EQ(f.alarm(), k >= 4 && sum > 40);
    if (k < 30) {
      EXPECT_FALSE(f.alarm());
    }
    alarmed = alarmed || f.alarm();
  }
  EXPECT_TRUE(alarmed);
}

TEST(ManoeuvreEstimator, RefusesBadSettingsAndInputs) {
  ManoeuvreEstimatorSettings s;
  s.nis_window = -1;
  EXPECT_THROW(TransientManoeuvreEstimator{s}, std::invalid_argument);
  s.nis_window = 3;
  s.nis_threshold = 0;
  EXPECT_THROW(TransientManoeuvreEstimator{s}, std::invalid_argument);
  TransientManoeuvreEstimator f;
  EXPECT_THROW(f.init(Vector6::Zero(), -P0()), std::invalid_argument);
  f.init(Vector6::Zero(), P0());
  const Cw cw;
  const Eigen::Vector3d nan(std::nan(""), 0, 0);
  EXPECT_EQ(f.step(cw.Phi(), cw.Qd(), cw.Gamma(), nan, R(), Eigen::Vector3d::Zero(), 1), FilterStatus::NonFiniteInput);
  EXPECT_EQ(f.step(cw.Phi(), cw.Qd(), cw.Gamma(), Eigen::Vector3d::Zero(), -R(), Eigen::Vector3d::Zero(), 1),
            FilterStatus::InnovationCovarianceNotPD);
}

}  // namespace
