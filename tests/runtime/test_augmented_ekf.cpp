// The augmented EKF and its prior-covariance policies (docs/maths.md §31.4): each policy
// reduces to the plain EKF bit for bit where the maths says it must (002-U3), the fading
// factors of (211) on synthetic residuals (002-U4), the adaptive-Q law of (210) on a
// synthetic estimate history (002-U5), positive definiteness over a run, and the stop on a
// non-finite state.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "hinf/models/linear.hpp"
#include "hinf/models/rigid_body.hpp"
#include "hinf/models/star_tracker.hpp"
#include "hinf/runtime/augmented_ekf.hpp"
#include "hinf/runtime/ekf.hpp"

using namespace hinf::runtime;
using hinf::models::RigidBodyAttitudeProcess;
using hinf::models::RigidBodyParameters;
using StarTracker = hinf::models::StarTrackerMeasurement<2>;
using State = RigidBodyAttitudeProcess::State;
using Cov9 = Eigen::Matrix<double, 9, 9>;
using Obs6 = Eigen::Matrix<double, 6, 1>;

namespace {

constexpr double kDt = 1.0;
constexpr double kQ = 1e-14;

RigidBodyAttitudeProcess process() {
  RigidBodyParameters p;
  p.inertia = Eigen::Vector3d(20, 18, 15).asDiagonal();
  p.sample_time = kDt;
  p.substeps = 1;
  return RigidBodyAttitudeProcess(p);
}
StarTracker star_tracker() { return StarTracker({Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1)}); }

Cov9 initial_covariance() {
  Eigen::Matrix<double, 9, 1> s;
  s << 1e-2, 1e-2, 1e-2, 1e-4, 1e-4, 1e-4, 1e-5, 1e-5, 1e-5;
  return s.array().square().matrix().asDiagonal();
}

// A truth with a slowly turning torque and its star-tracker stream (σ = 1e-5 rad).
struct Stream {
  std::vector<State> truth;
  std::vector<Obs6> z;
};
Stream make_stream(int steps, unsigned seed) {
  const auto model = process();
  const auto st = star_tracker();
  std::mt19937_64 g(seed);
  std::normal_distribution<double> n(0, 1e-5);
  Stream s;
  State x = State::Zero();
  x(3) = 1;
  for (int k = 0; k < steps; ++k) {
    x.segment<3>(7) << -1e-5 * std::sin(6e-3 * k), 1e-5 * std::sin(4e-3 * k), -1e-5 * std::sin(8e-3 * k);
    x = model.f(x, Eigen::Vector3d::Zero());
    Obs6 z = st.h(x);
    for (int i = 0; i < 6; ++i) z(i) += n(g);
    s.truth.push_back(x);
    s.z.push_back(z);
  }
  return s;
}

State initial_state() {
  State x = State::Zero();
  x(3) = 1;
  return x;
}

template <class Policy>
AugmentedEkf<RigidBodyAttitudeProcess, StarTracker, Policy> make_filter(const Policy& policy) {
  const auto model = process();
  AugmentedEkf<RigidBodyAttitudeProcess, StarTracker, Policy> f(model, star_tracker(), model.discrete_process_noise(kQ),
                                                                Eigen::Matrix<double, 6, 6>::Identity() * 1e-10, policy);
  f.init(initial_state(), initial_covariance());
  return f;
}

// Runs `filter` over the stream beside Ekf::predict + Ekf::update and requires x and P to be
// bit-identical after every step.
template <class Filter>
void expect_bit_identical_to_ekf(Filter& filter, const Stream& s) {
  const auto model = process();
  Ekf<RigidBodyAttitudeProcess, StarTracker> ekf(model, star_tracker(), model.discrete_process_noise(kQ),
                                                 Eigen::Matrix<double, 6, 6>::Identity() * 1e-10);
  ekf.init(initial_state(), initial_covariance());
  for (std::size_t k = 0; k < s.z.size(); ++k) {
    ASSERT_EQ(ekf.predict(Eigen::Vector3d::Zero()), FilterStatus::Ok);
    ASSERT_EQ(ekf.update(s.z[k]), FilterStatus::Ok);
    filter.step(Eigen::Vector3d::Zero(), s.z[k]);
    ASSERT_TRUE((filter.x().array() == ekf.x().array()).all()) << "step " << k;
    ASSERT_TRUE((filter.P().array() == ekf.P().array()).all()) << "step " << k;
  }
}

}  // namespace

// 002-U3
TEST(AugmentedEkf, PlainPriorIsTheEkfBitForBit) {
  const Stream s = make_stream(400, 1);
  auto f = make_filter(PlainPrior<9, 6>{});
  expect_bit_identical_to_ekf(f, s);
}

TEST(AugmentedEkf, StrongTrackingWithUnitCapIsTheEkfBitForBit) {
  const Stream s = make_stream(400, 2);
  StrongTrackingSettings<9> st;
  st.weakening = 1;
  st.alpha << 1, 1, 1, 1, 1, 1, 5, 5, 5;
  st.lambda_max = 1;
  auto f = make_filter(StrongTracking<9, 6>(st));
  expect_bit_identical_to_ekf(f, s);
  EXPECT_GT(f.policy().cap_hits(), 0);  // the factors did want to fade: the cap was doing the work
}

TEST(AugmentedEkf, AdaptiveQWithConstantIntensityIsTheEkfBitForBit) {
  const Stream s = make_stream(400, 3);
  AdaptiveQSettings a;
  a.state_offset = 7;
  a.error_offset = 6;
  a.sample_time = kDt;
  a.window = 10;
  a.epsilon = 0;  // s ε² F(κ) = 0: Q_T = Q_floor = Q_initial, constant
  a.floor = kQ;
  a.initial = kQ;
  auto f = make_filter(AdaptiveQ<9, 6, 3>(a));
  expect_bit_identical_to_ekf(f, s);
}

// 002-U4: matched residuals (|γ|² = tr(HΦPΦᵀHᵀ) + tr R, K_b = 1, α = 1) give c = 1, λ = 1;
// with V₀ doubled, c and λ_i = max(1, α_i c) as (211) gives them.
TEST(AugmentedEkf, FadingFactorsAreOneOnMatchedResiduals) {
  std::mt19937_64 g(4);
  std::normal_distribution<double> n(0, 1);
  Cov9 A;
  for (int i = 0; i < 81; ++i) A(i) = n(g);
  const Cov9 PhiPPhiT = A * A.transpose() * 1e-6 + Cov9::Identity() * 1e-8;
  const auto x = initial_state();
  const auto H = star_tracker().H(x);
  const Eigen::Matrix<double, 6, 6> R = Eigen::Matrix<double, 6, 6>::Identity() * 1e-10;
  const Cov9 Q = process().discrete_process_noise(kQ);  // H Q Hᵀ = 0 here (H Γ = 0)
  const double matched = (H * PhiPPhiT * H.transpose()).trace() + R.trace();
  Obs6 gamma = Obs6::Ones().normalized() * std::sqrt(matched);

  StrongTrackingSettings<9> s;
  s.weakening = 1;
  StrongTracking<9, 6> st(s);
  EXPECT_EQ(st.fading_factors(PhiPPhiT, Q, H, gamma, R), FilterStatus::Ok);
  EXPECT_NEAR(st.c(), 1.0, 1e-12);
  EXPECT_LT((st.lambda().array() - 1).abs().maxCoeff(), 1e-12);

  s.alpha << 1, 1, 1, 1.5, 1.5, 1.5, 3, 3, 3;
  StrongTracking<9, 6> doubled(s);
  gamma *= std::sqrt(2.0);  // V₀ = 2 γγᵀ
  EXPECT_EQ(doubled.fading_factors(PhiPPhiT, Q, H, gamma, R), FilterStatus::Ok);
  // c = tr(2 matched − R) / Σ α_i M_ii, M = ΦPΦᵀ HᵀH; only the attitude block has M_ii ≠ 0
  const Cov9 M = PhiPPhiT * H.transpose() * H;
  double denominator = 0;
  for (int i = 0; i < 9; ++i) denominator += s.alpha(i) * M(i, i);
  const double c = (2 * matched - R.trace()) / denominator;
  EXPECT_NEAR(doubled.c(), c, 1e-12 * c);
  EXPECT_GT(c, 1.0);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(doubled.lambda()(i), std::max(1.0, s.alpha(i) * c), 1e-12 * c);
}

// The symmetric form keeps P symmetric positive definite over a whole run with strong
// fading; the literal product ΛΦPΦᵀ is not symmetric when the λ_i differ.
TEST(AugmentedEkf, SymmetricFadingKeepsCovariancePositiveDefinite) {
  const Stream s = make_stream(1500, 5);
  StrongTrackingSettings<9> st;
  st.forgetting = 0.95;
  st.weakening = 2;
  st.alpha << 1, 1, 1, 1, 1, 1, 2, 2, 2;
  auto f = make_filter(StrongTracking<9, 6>(st));
  long faded = 0;
  for (std::size_t k = 0; k < s.z.size(); ++k) {
    const FilterStatus status = f.step(Eigen::Vector3d::Zero(), s.z[k]);
    ASSERT_TRUE(status == FilterStatus::Ok || status == FilterStatus::FadingFactorCapped) << to_string(status);
    ASSERT_TRUE((f.P().array() == f.P().transpose().array()).all());
    ASSERT_GT(Eigen::SelfAdjointEigenSolver<Cov9>(f.P()).eigenvalues().minCoeff(), 0.0) << "step " << k;
    if (f.policy().lambda().maxCoeff() > 1) ++faded;
  }
  EXPECT_GT(faded, 0);
  const Cov9 P = f.P();
  Eigen::Matrix<double, 9, 1> lambda = Eigen::Matrix<double, 9, 1>::Ones();
  lambda.tail<3>().setConstant(4);
  const Cov9 literal = lambda.asDiagonal() * P;
  EXPECT_GT((literal - literal.transpose()).norm(), 1e-3 * literal.norm());
}

// 002-U5: a torque estimate growing linearly at κ (exact binary fractions) gives, after m
// corrections, Q_T = s ε² κκᵀ (`outer`) and s ε² diag(κ²) (`diag`) exactly.
TEST(AugmentedEkf, AdaptiveLawOnALinearHistory) {
  const Eigen::Vector3d kappa(0.25, -0.5, 0.125);
  for (const AdaptiveQLaw law : {AdaptiveQLaw::Outer, AdaptiveQLaw::Diagonal}) {
    AdaptiveQSettings a;
    a.state_offset = 7;
    a.error_offset = 6;
    a.sample_time = 0.5;
    a.window = 4;
    a.scale = 2;
    a.epsilon = 4;
    a.initial = 3;
    a.law = law;
    AdaptiveQ<9, 6, 3> q(a);
    State x = initial_state();
    q.start(x);
    for (int k = 1; k <= 6; ++k) {
      x.segment<3>(7) = kappa * (k * a.sample_time);
      q.corrected(x);
      if (k < a.window) {
        EXPECT_TRUE((q.intensity().array() == (Eigen::Matrix3d::Identity() * 3).array()).all());
      }
    }
    const Eigen::Matrix3d expected = law == AdaptiveQLaw::Outer ? Eigen::Matrix3d(kappa * kappa.transpose() * 32)
                                                                 : Eigen::Matrix3d(kappa.array().square().matrix().asDiagonal()) * 32;
    EXPECT_TRUE((q.intensity().array() == expected.array()).all()) << q.intensity();
    EXPECT_TRUE((q.rate().array() == kappa.array()).all());
  }
  AdaptiveQSettings bad;
  bad.window = 0;
  EXPECT_THROW((AdaptiveQ<9, 6, 3>(bad)), std::invalid_argument);
  StrongTrackingSettings<9> st;
  st.forgetting = 0;
  EXPECT_THROW((StrongTracking<9, 6>(st)), std::invalid_argument);
}

// A step whose covariance overflows is undone and stops the filter; later steps change nothing.
TEST(AugmentedEkf, NonFiniteStateStopsTheFilter) {
  using Model = hinf::models::LinearModel<1, 1>;
  using Meas = hinf::models::LinearMeasurement<1, 1>;
  Eigen::Matrix<double, 1, 1> F, G, H;
  F << 1e200;
  G << 0;
  H << 1;
  AugmentedEkf<Model, Meas, PlainPrior<1, 1>> f(Model(F, G), Meas(H), Eigen::Matrix<double, 1, 1>::Zero(),
                                                Eigen::Matrix<double, 1, 1>::Identity(), PlainPrior<1, 1>{});
  f.init(Eigen::Matrix<double, 1, 1>::Zero(), Eigen::Matrix<double, 1, 1>::Identity());
  const Eigen::Matrix<double, 1, 1> u = Eigen::Matrix<double, 1, 1>::Zero(), y = Eigen::Matrix<double, 1, 1>::Ones();
  EXPECT_EQ(f.step(u, y), FilterStatus::StateNotFinite);
  EXPECT_TRUE(f.stopped());
  EXPECT_EQ(f.P()(0, 0), 1.0);
  EXPECT_EQ(f.x()(0), 0.0);
  EXPECT_EQ(f.step(u, y), FilterStatus::Stopped);
  EXPECT_EQ(f.P()(0, 0), 1.0);
}
