// Cost of one step: LtiFilter (dynamic), FixedLtiFilter<6,3,6>, a plain C-style loop doing
// the same arithmetic as docs/maths.md (5)-(6), and EKF / REKF predict+update on the Hill model with a
// Cartesian (and range/azimuth/elevation) measurement. Inputs cycle through a
// precomputed table so nothing is constant-folded. Seed 001: the transient manoeuvre
// estimator's step beside the EKF's on the same CW model, and the cost of the elliptic model's
// sample (Kepler, Φ = exp(A Δt), Van Loan's Q_d) beside the closed-form CW transition.
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

#include "hinf/runtime/augmented_ekf.hpp"
#include "hinf/runtime/ekf.hpp"
#include "hinf/runtime/manoeuvre_estimator.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/models/cartesian_position.hpp"
#include "hinf/models/elliptic_relative.hpp"
#include "hinf/models/two_body.hpp"
#include "hinf/models/hill.hpp"
#include "hinf/models/range_azimuth_elevation.hpp"
#include "hinf/models/rigid_body.hpp"
#include "hinf/models/star_tracker.hpp"
#include "hinf/runtime/rekf.hpp"

namespace {
using namespace hinf::runtime;
constexpr int kN = 6, kM = 3, kL = 6, kTable = 1024;

struct Gains {
  Eigen::MatrixXd A, B, C;
  std::vector<Eigen::Vector3d> ys;
  Gains() {
    std::mt19937 g(1);
    std::uniform_real_distribution<double> u(-1, 1);
    A = Eigen::MatrixXd(kN, kN);
    B = Eigen::MatrixXd(kN, kM);
    C = Eigen::MatrixXd(kL, kN);
    for (int i = 0; i < A.size(); ++i) A(i) = u(g);
    for (int i = 0; i < B.size(); ++i) B(i) = u(g);
    for (int i = 0; i < C.size(); ++i) C(i) = u(g);
    A *= 0.9 / A.norm();
    for (int k = 0; k < kTable; ++k) ys.emplace_back(u(g), u(g), u(g));
  }
};
const Gains& gains() {
  static const Gains g;
  return g;
}

void BM_LtiFilterDynamic(benchmark::State& st) {
  const Gains& G = gains();
  LtiFilter f(G.A, G.B, G.C);
  Eigen::VectorXd y(kM);
  int k = 0;
  for (auto _ : st) {
    y = G.ys[k++ & (kTable - 1)];
    benchmark::DoNotOptimize(f.step(y).data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_LtiFilterDynamic);

void BM_FixedLtiFilter_6_3_6(benchmark::State& st) {
  const Gains& G = gains();
  FixedLtiFilter<6, 3, 6> f(G.A, G.B, G.C);
  int k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(f.step(G.ys[k++ & (kTable - 1)]).data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_FixedLtiFilter_6_3_6);

// Hand-written reference: row-major arrays, double loops.
void BM_PlainCLoop_6_3_6(benchmark::State& st) {
  const Gains& G = gains();
  double A[kN][kN], B[kN][kM], C[kL][kN], x[kN] = {0}, xn[kN], z[kL];
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) A[i][j] = G.A(i, j);
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kM; ++j) B[i][j] = G.B(i, j);
  for (int i = 0; i < kL; ++i)
    for (int j = 0; j < kN; ++j) C[i][j] = G.C(i, j);
  int k = 0;
  for (auto _ : st) {
    const double* y = G.ys[k++ & (kTable - 1)].data();
    for (int i = 0; i < kL; ++i) {
      double s = 0.0;
      for (int j = 0; j < kN; ++j) s += C[i][j] * x[j];
      z[i] = s;
    }
    for (int i = 0; i < kN; ++i) {
      double s = 0.0;
      for (int j = 0; j < kN; ++j) s += A[i][j] * x[j];
      for (int j = 0; j < kM; ++j) s += B[i][j] * y[j];
      xn[i] = s;
    }
    for (int i = 0; i < kN; ++i) x[i] = xn[i];
    benchmark::DoNotOptimize(z);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_PlainCLoop_6_3_6);

hinf::models::HillModel::Gain paper_K() {
  hinf::models::HillModel::Gain K;
  K << -2.2541, -0.0071, -0.0072, -22.3975, 2.3256, 1.9369, -0.0104, -2.2493, -0.0055, 2.3259, -23.7456, 1.4544,
      -0.0072, -0.0055, -2.2471, 1.9357, 1.4552, -24.2818;
  return K;
}
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;
Mat6 paper_Q() {
  Vec6 b;
  b << 0.05, 0.05, 0.05, 0.001, 0.001, 0.001;
  return (b.array() * b.array()).matrix().asDiagonal();
}
Vec6 x0() { return (Vec6() << 630, 520, 1000, 0, 0, 0).finished(); }

void BM_EkfStep_Hill_Cartesian(benchmark::State& st) {
  const Gains& G = gains();
  const hinf::models::HillModel hill(7.2722e-5, 1000.0, 0.1, paper_K());
  Ekf<hinf::models::HillModel, hinf::models::CartesianPosition> ekf(hill, {}, paper_Q(), 0.01 * Eigen::Matrix3d::Identity());
  ekf.init(x0(), 100.0 * Mat6::Identity());
  const Eigen::Vector3d base(600, 550, 1040);
  int k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(ekf.predict(Eigen::Vector3d::Zero()));
    benchmark::DoNotOptimize(ekf.update(base + G.ys[k++ & (kTable - 1)]));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_EkfStep_Hill_Cartesian);

void BM_EkfStep_Hill_RangeAzimuthElevation(benchmark::State& st) {
  const Gains& G = gains();
  const hinf::models::HillModel hill(7.2722e-5, 1000.0, 0.1, paper_K());
  const hinf::models::RangeAzimuthElevation rae;
  Ekf<hinf::models::HillModel, hinf::models::RangeAzimuthElevation> ekf(hill, rae, paper_Q(),
                                                            Eigen::Vector3d(0.01, 1e-8, 1e-8).asDiagonal());
  ekf.init(x0(), 100.0 * Mat6::Identity());
  const Eigen::Vector3d base = rae.h((Vec6() << 600, 550, 1040, 0, 0, 0).finished());
  int k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(ekf.predict(Eigen::Vector3d::Zero()));
    benchmark::DoNotOptimize(ekf.update(base + 1e-3 * G.ys[k++ & (kTable - 1)]));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_EkfStep_Hill_RangeAzimuthElevation);

void BM_RekfStep_Hill_Cartesian(benchmark::State& st) {
  const Gains& G = gains();
  const hinf::models::HillModel hill(7.2722e-5, 1000.0, 0.1, paper_K());
  Rekf<hinf::models::HillModel, hinf::models::CartesianPosition> rekf(
      hill, {}, paper_Q(), 0.01 * Eigen::Matrix3d::Identity(), 100.0, 1e-3 * Mat6::Identity(),
      1e-3 * Eigen::Matrix3d::Identity(), 0.1 * Mat6::Identity());
  rekf.init(x0(), 100.0 * Mat6::Identity());
  const Eigen::Vector3d base(600, 550, 1040);
  int k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(rekf.predict(Eigen::Vector3d::Zero()));
    benchmark::DoNotOptimize(rekf.update(base + G.ys[k++ & (kTable - 1)]));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_RekfStep_Hill_Cartesian);

// Seed 002's gyroless attitude filter (docs/maths.md §31): the plain Ekf's predict + update
// on the rigid body and star tracker, and the AugmentedEkf's step with each policy on the
// same stream — the policy's cost is the difference.
using RigidBody = hinf::models::RigidBodyAttitudeProcess;
using StarTracker2 = hinf::models::StarTrackerMeasurement<2>;
RigidBody rigid_body() {
  hinf::models::RigidBodyParameters p;
  p.inertia = Eigen::Vector3d(20, 18, 15).asDiagonal();
  return RigidBody(p);
}
RigidBody::State rigid_body_x0() {
  RigidBody::State x = RigidBody::State::Zero();
  x(3) = 1;
  return x;
}
StarTracker2::Vector star_tracker_y(const Gains& G, int k) {
  StarTracker2::Vector y;
  y << 1, 0, 0, 0, 0, 1;
  y.head<3>() += 1e-5 * G.ys[k & (kTable - 1)];
  y.tail<3>() -= 1e-5 * G.ys[(k + 7) & (kTable - 1)];
  return y;
}
const Eigen::Matrix<double, 6, 6> kStarTrackerR = Eigen::Matrix<double, 6, 6>::Identity() * 1e-10;
const Eigen::Matrix<double, 9, 9> kRigidBodyP0 = Eigen::Matrix<double, 9, 9>::Identity() * 1e-6;

void BM_EkfStep_RigidBody_StarTracker(benchmark::State& st) {
  const Gains& G = gains();
  const RigidBody model = rigid_body();
  Ekf<RigidBody, StarTracker2> ekf(model, StarTracker2({Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1)}),
                                   model.discrete_process_noise(1e-14), kStarTrackerR);
  ekf.init(rigid_body_x0(), kRigidBodyP0);
  int k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(ekf.predict(Eigen::Vector3d::Zero()));
    benchmark::DoNotOptimize(ekf.update(star_tracker_y(G, k++)));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_EkfStep_RigidBody_StarTracker);

template <class Policy>
void augmented_ekf_steps(benchmark::State& st, const Policy& policy) {
  const Gains& G = gains();
  const RigidBody model = rigid_body();
  AugmentedEkf<RigidBody, StarTracker2, Policy> f(model, StarTracker2({Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1)}),
                                                  model.discrete_process_noise(1e-14), kStarTrackerR, policy);
  f.init(rigid_body_x0(), kRigidBodyP0);
  int k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(f.step(Eigen::Vector3d::Zero(), star_tracker_y(G, k++)));
    benchmark::ClobberMemory();
  }
}
void BM_AugmentedEkfStep_Plain(benchmark::State& st) { augmented_ekf_steps(st, PlainPrior<9, 6>{}); }
void BM_AugmentedEkfStep_StrongTracking(benchmark::State& st) {
  StrongTrackingSettings<9> s;
  s.weakening = 2;
  s.alpha << 1, 1, 1, 1, 1, 1, 2, 2, 2;
  augmented_ekf_steps(st, StrongTracking<9, 6>(s));
}
void BM_AugmentedEkfStep_AdaptiveQ(benchmark::State& st) {
  AdaptiveQSettings a;
  a.state_offset = 7;
  a.error_offset = 6;
  a.initial = 1e-14;
  augmented_ekf_steps(st, AdaptiveQ<9, 6, 3>(a));
}
BENCHMARK(BM_AugmentedEkfStep_Plain);
BENCHMARK(BM_AugmentedEkfStep_StrongTracking);
BENCHMARK(BM_AugmentedEkfStep_AdaptiveQ);

// Seed 001: the estimator's step (prediction, Joseph update, Û and both covariances, the NIS
// window) with a fixed CW sample, the same work as BM_EkfStep_Hill_Cartesian plus Û.
void BM_ManoeuvreEstimatorStep(benchmark::State& st) {
  const Gains& G = gains();
  namespace m = hinf::models;
  const double n = 1.156874e-3;
  const Mat6 Phi = m::clohessy_wiltshire_transition(n, 1.0);
  Mat6 W = Mat6::Zero();
  W.bottomRightCorner<3, 3>() = 0.25 * Eigen::Matrix3d::Identity();
  const Mat6 Qd = m::sampled_white_noise_intensity<6>(m::clohessy_wiltshire_A(n), W, 1.0);
  ManoeuvreEstimatorSettings s;
  s.nis_window = 10;
  s.nis_threshold = 59.7;
  TransientManoeuvreEstimator f(s);
  f.init(x0(), Mat6::Identity());
  const Eigen::Matrix3d R = 4 * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d base(600, 550, 1040);
  int k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(f.step(Phi, Qd, m::Matrix63::Zero(), base + G.ys[k++ & (kTable - 1)], R,
                                    Eigen::Vector3d::Zero(), 1.0));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_ManoeuvreEstimatorStep);

// One sample of the elliptic relative model (e = 0.1): the reference orbit by Kepler, A(t),
// Φ, Q_d by Van Loan; `transition` frozen or exact (RK4, 10 steps).
void elliptic_model_steps(benchmark::State& st, hinf::models::RelativeTransition transition) {
  namespace m = hinf::models;
  m::OrbitalElements el;
  el.a = 7500e3;
  el.e = 0.1;
  m::EllipticRelativeModel::Options o;
  o.transition = transition;
  o.exact_substeps = 10;
  const m::EllipticRelativeModel model(m::KeplerOrbit(m::state_from_elements(el, m::kEarthMu), m::kEarthMu), o);
  double t = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(model.step(t, 1.0, false));
    t += 1;
    benchmark::ClobberMemory();
  }
}
void BM_EllipticModelSample_Frozen(benchmark::State& st) { elliptic_model_steps(st, hinf::models::RelativeTransition::Frozen); }
void BM_EllipticModelSample_Exact10(benchmark::State& st) { elliptic_model_steps(st, hinf::models::RelativeTransition::Exact); }
BENCHMARK(BM_EllipticModelSample_Frozen);
BENCHMARK(BM_EllipticModelSample_Exact10);

// The closed-form CW transition: what the frozen exponential replaces on a circular orbit.
void BM_CwTransitionClosedForm(benchmark::State& st) {
  double t = 1;
  for (auto _ : st) {
    benchmark::DoNotOptimize(hinf::models::clohessy_wiltshire_transition(1.156874e-3, t));
    t += 1e-6;
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_CwTransitionClosedForm);

}  // namespace

BENCHMARK_MAIN();
