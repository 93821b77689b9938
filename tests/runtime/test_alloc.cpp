// Zero heap allocations per step. This executable replaces the global operator new
// family AND interposes malloc/calloc/realloc/aligned allocation (glibc: forwarding to
// __libc_malloc & co.), because Eigen allocates with std::malloc, not operator new.
// Counting is switched on only around the code under test.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <random>

#include "hinf/runtime/augmented_ekf.hpp"
#include "hinf/runtime/ekf.hpp"
#include "hinf/runtime/manoeuvre_estimator.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/models/cartesian_position.hpp"
#include "hinf/models/elliptic_relative.hpp"
#include "hinf/models/two_body.hpp"
#include "hinf/models/gps_ins.hpp"
#include "hinf/models/hill.hpp"
#include "hinf/models/range_azimuth_elevation.hpp"
#include "hinf/models/rigid_body.hpp"
#include "hinf/models/star_tracker.hpp"
#include "hinf/runtime/rekf.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
inline void count() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
}
struct CountScope {
  CountScope() {
    g_allocations = 0;
    g_counting = true;
  }
  ~CountScope() { g_counting = false; }
  long count() const { return g_allocations.load(); }
};
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);

void* malloc(std::size_t n) {
  count();
  return __libc_malloc(n);
}
void* calloc(std::size_t a, std::size_t b) {
  count();
  return __libc_calloc(a, b);
}
void* realloc(void* p, std::size_t n) {
  count();
  return __libc_realloc(p, n);
}
void* memalign(std::size_t al, std::size_t n) {
  count();
  return __libc_memalign(al, n);
}
void* aligned_alloc(std::size_t al, std::size_t n) {
  count();
  return __libc_memalign(al, n);
}
int posix_memalign(void** p, std::size_t al, std::size_t n) {
  count();
  *p = __libc_memalign(al, n);
  return *p ? 0 : 12;  // ENOMEM
}
}

void* operator new(std::size_t n) {
  count();
  if (void* p = __libc_malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  count();
  if (void* p = __libc_malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
// The replaced operator new allocates with __libc_malloc, so free() is its match; GCC's
// -Wmismatched-new-delete cannot see the replacement once a std::vector's deallocation is
// inlined here (AdaptiveQ's window) and warns falsely.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

TEST(Allocations, CounterSeesEigenAndNew) {
  // The counter must be able to fail: a dynamic Eigen vector (std::malloc) and a call of
  // operator new (called directly: a new-expression may be elided by the optimiser) count.
  long n_eigen = 0, n_new = 0;
  {
    CountScope s;
    Eigen::VectorXd v(100);
    v.setZero();
    n_eigen = s.count();
    EXPECT_EQ(v.sum(), 0.0);
  }
  {
    CountScope s;
    void* volatile q = ::operator new(64);
    n_new = s.count();
    ::operator delete(q);
  }
  EXPECT_EQ(n_eigen, 1);
  EXPECT_EQ(n_new, 1);
}

TEST(Allocations, DynamicLtiFilterStepDoesNotAllocate) {
  std::mt19937 g(1);
  std::normal_distribution<double> nd;
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(6, 6);
  A *= 0.9 / A.norm();
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(6, 3), C = Eigen::MatrixXd::Random(6, 6);
  hinf::runtime::LtiFilter f(A, B, C);
  Eigen::VectorXd y(3), z0 = Eigen::VectorXd::Ones(6);
  Eigen::Vector3d y_fixed(1.0, 2.0, 3.0);
  double sink = 0.0;
  long n = 0;
  {
    CountScope s;
    f.init(z0);
    for (int k = 0; k < 1000; ++k) {
      y << nd(g), nd(g), nd(g);
      sink += f.step(y)(0);
      sink += f.step(y_fixed)(1);  // fixed-size argument binds to Ref without a copy
    }
    sink += f.output()(2);
    n = s.count();
  }
  EXPECT_EQ(n, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(Allocations, FixedLtiFilterStepDoesNotAllocate) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(6, 6);
  A *= 0.9 / A.norm();
  hinf::runtime::FixedLtiFilter<6, 3, 6> f(A, Eigen::MatrixXd::Random(6, 3), Eigen::MatrixXd::Random(6, 6));
  double sink = 0.0;
  long n = 0;
  {
    CountScope s;
    for (int k = 0; k < 1000; ++k) sink += f.step(Eigen::Vector3d(k, 1.0, -1.0))(0);
    n = s.count();
  }
  EXPECT_EQ(n, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(Allocations, EkfAndRekfStepsDoNotAllocate) {
  using namespace hinf::runtime;
  using hinf::models::CartesianPosition;
  using hinf::models::HillModel;
  using hinf::models::RangeAzimuthElevation;
  const HillModel hill(7.2722e-5, 1000.0, 0.1, hinf::models::Discretisation::ZeroOrderHold);
  Eigen::Matrix<double, 6, 1> x0;
  x0 << 600, 550, 1040, 0.02, -0.08, 0.03;
  const Eigen::Matrix<double, 6, 6> Q = 1e-6 * Eigen::Matrix<double, 6, 6>::Identity();
  const Eigen::Matrix<double, 6, 6> P0 = 100.0 * Eigen::Matrix<double, 6, 6>::Identity();
  Ekf<HillModel, CartesianPosition> ekf(hill, CartesianPosition{}, Q, 0.01 * Eigen::Matrix3d::Identity());
  Ekf<HillModel, RangeAzimuthElevation> ekf_rae(hill, RangeAzimuthElevation{}, Q,
                                                Eigen::Vector3d(0.1, 1e-4, 1e-4).asDiagonal());
  Rekf<HillModel, CartesianPosition> rekf(hill, CartesianPosition{}, Q, 0.01 * Eigen::Matrix3d::Identity(), 100.0,
                                          1e-3 * Eigen::Matrix<double, 6, 6>::Identity(),
                                          1e-3 * Eigen::Matrix3d::Identity(),
                                          0.1 * Eigen::Matrix<double, 6, 6>::Identity());
  ekf.init(x0, P0);
  ekf_rae.init(x0, P0);
  rekf.init(x0, P0);
  const RangeAzimuthElevation rae;
  long n = 0;
  int not_ok = 0;
  {
    CountScope s;
    Eigen::Matrix<double, 6, 1> x = x0;
    for (int k = 0; k < 500; ++k) {
      x = hill.f(x, Eigen::Vector3d::Zero());
      not_ok += ekf.predict(Eigen::Vector3d::Zero()) != FilterStatus::Ok;
      not_ok += ekf.update(x.head<3>()) != FilterStatus::Ok;
      not_ok += ekf_rae.predict(Eigen::Vector3d::Zero()) != FilterStatus::Ok;
      not_ok += ekf_rae.update(rae.h(x)) != FilterStatus::Ok;
      not_ok += rekf.predict(Eigen::Vector3d::Zero()) != FilterStatus::Ok;
      not_ok += rekf.update(x.head<3>()) != FilterStatus::Ok;
    }
    n = s.count();
  }
  EXPECT_EQ(n, 0);
  EXPECT_EQ(not_ok, 0);
}

// The 15-state GPS/INS model with its manifold hooks, a new epoch and new REKF uncertainty
// matrices at every step (docs/maths.md §29): no allocation either.
TEST(Allocations, GpsInsEkfAndRekfStepsDoNotAllocate) {
  using namespace hinf::runtime;
  using namespace hinf::models;
  GpsInsParameters p;
  p.orbit_rate = 1.101573e-3;
  p.flyaround_rate = p.orbit_rate;
  p.inertia = Eigen::Vector3d(1000, 1200, 900).asDiagonal();
  p.baselines = {Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(-2, 2, 0)};
  constexpr int NZ = GpsInsMeasurement::NZ;
  using Mat15 = Eigen::Matrix<double, 15, 15>;
  const Eigen::Matrix<double, NZ, NZ> R = 1e-4 * Eigen::Matrix<double, NZ, NZ>::Identity();
  Ekf<GpsInsProcess, GpsInsMeasurement> ekf(GpsInsProcess{p}, GpsInsMeasurement{p}, 1e-12 * Mat15::Identity(), R);
  Rekf<GpsInsProcess, GpsInsMeasurement> rekf(GpsInsProcess{p}, GpsInsMeasurement{p}, 1e-12 * Mat15::Identity(), R,
                                              1.0, Mat15::Zero(), Eigen::Matrix<double, NZ, NZ>::Zero(),
                                              Mat15::Zero());
  GpsInsEpoch e;
  e.r_target = Eigen::Vector3d(6899807.0, 0, 0);
  for (int j = 0; j < kGpsInsSatellites; ++j) e.r_satellite[j] = e.r_target + 2.0e7 * Eigen::Vector3d::Unit(j % 3);
  e.r_satellite[3] = e.r_target + 2.0e7 * Eigen::Vector3d(1, 1, 1).normalized();
  Eigen::Matrix<double, 15, 1> x = Eigen::Matrix<double, 15, 1>::Zero(), s;
  x.head<3>() << 100, 0, -173.21;
  s.setConstant(1.0);  // L = I: γ²I − LPLᵀ = 0.99 I at P0
  ekf.init(x, Mat15::Identity() * 1e-2);
  rekf.init(x, Mat15::Identity() * 1e-2);
  GpsInsProcessNoise q;
  q.accel_sigma = 1e-6;
  q.inertia_uncertainty_fraction = 0.3;
  long n = 0;
  int not_ok = 0;
  {
    CountScope scope;
    for (int k = 0; k < 200; ++k) {
      e.R_FR = rotation_3(p.flyaround_rate * k);
      e.R_RI = rotation_3(p.orbit_rate * k);
      ekf.mutable_model().set_epoch(e);
      rekf.mutable_model().set_epoch(e);
      ekf.mutable_measurement().set_epoch(e);
      rekf.mutable_measurement().set_epoch(e);
      const auto u = gps_ins_rekf_uncertainty(rekf.model().continuous_jacobian(rekf.x()),
                                              rekf.measurement().H(rekf.x()), s, 1.0, 0.1, 1e-3);
      rekf.set_uncertainty(u.A, u.C, u.L);
      rekf.set_Q(gps_ins_process_noise(p, q, Eigen::Vector3d(1e-3, 0, 0)));
      not_ok += ekf.predict(Eigen::Vector3d::Zero()) != FilterStatus::Ok;
      not_ok += rekf.predict(Eigen::Vector3d::Zero()) != RekfStatus::Ok;
      const GpsInsMeasurement::Vector y = ekf.measurement().h(x);
      not_ok += ekf.update(y) != FilterStatus::Ok;
      not_ok += rekf.update(y) != RekfStatus::Ok;
    }
    n = scope.count();
  }
  EXPECT_EQ(n, 0);
  EXPECT_EQ(not_ok, 0);
}

// The augmented EKF of seed 002 with each prior-covariance policy: the constructors allocate
// (AdaptiveQ's window), step() does not — the RK4 prediction, Φ = exp(FΔt), the fading
// factors, the adaptive law and the Joseph update included.
template <class Policy>
long augmented_ekf_step_allocations(const Policy& policy) {
  using Process = hinf::models::RigidBodyAttitudeProcess;
  using Tracker = hinf::models::StarTrackerMeasurement<2>;
  hinf::models::RigidBodyParameters p;
  p.inertia = Eigen::Vector3d(20, 18, 15).asDiagonal();
  const Process model(p);
  hinf::runtime::AugmentedEkf<Process, Tracker, Policy> f(
      model, Tracker({Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1)}), model.discrete_process_noise(1e-14),
      Eigen::Matrix<double, 6, 6>::Identity() * 1e-10, policy);
  Process::State x0 = Process::State::Zero();
  x0(3) = 1;
  f.init(x0, Eigen::Matrix<double, 9, 9>::Identity() * 1e-6);
  Tracker::Vector y;
  y << 1, 1e-5, -2e-5, 3e-5, 0, 1;
  CountScope s;
  for (int k = 0; k < 200; ++k) f.step(Eigen::Vector3d::Zero(), y);
  return s.count();
}

TEST(Allocations, AugmentedEkfStepsDoNotAllocate) {
  EXPECT_EQ(augmented_ekf_step_allocations(hinf::runtime::PlainPrior<9, 6>{}), 0);
  hinf::runtime::StrongTrackingSettings<9> st;
  st.weakening = 2;
  EXPECT_EQ(augmented_ekf_step_allocations(hinf::runtime::StrongTracking<9, 6>(st)), 0);
  hinf::runtime::AdaptiveQSettings a;
  a.state_offset = 7;
  a.error_offset = 6;
  a.window = 5;
  a.initial = 1e-14;
  EXPECT_EQ(augmented_ekf_step_allocations(hinf::runtime::AdaptiveQ<9, 6, 3>(a)), 0);
}

// Seed 001's estimator with its model: the reference orbit (Kepler), A(t), Φ = exp(A Δt) (frozen
// and exact), Van Loan's Q_d, Γ, and the estimator's step with the NIS window (allocated by
// the constructor) do not allocate.
TEST(Allocations, ManoeuvreEstimatorAndEllipticModelStepsDoNotAllocate) {
  namespace m = hinf::models;
  m::OrbitalElements el;
  el.a = 7000e3;
  el.e = 0.1;
  const m::KeplerOrbit ref(m::state_from_elements(el, m::kEarthMu), m::kEarthMu);
  m::EllipticRelativeModel::Options frozen, exact;
  exact.transition = m::RelativeTransition::Exact;
  exact.exact_substeps = 10;
  const m::EllipticRelativeModel models[2] = {m::EllipticRelativeModel(ref, frozen), m::EllipticRelativeModel(ref, exact)};
  hinf::runtime::ManoeuvreEstimatorSettings s;
  s.nis_window = 10;
  s.nis_threshold = 59.7;
  hinf::runtime::TransientManoeuvreEstimator f(s);
  Eigen::Matrix<double, 6, 1> x0;
  x0 << 1000, 50000, 0, 0, -10, 0;
  f.init(x0, Eigen::Matrix<double, 6, 6>::Identity());
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * 4;
  CountScope c;
  for (int k = 0; k < 50; ++k) {
    const m::SampledRelativeStep st = models[k % 2].step(k, 1.0, true);
    f.step(st.Phi, st.Qd, st.Gamma, x0.head<3>(), R, Eigen::Vector3d(0.1, 0, 0), 1.0);
  }
  EXPECT_EQ(c.count(), 0);
}
