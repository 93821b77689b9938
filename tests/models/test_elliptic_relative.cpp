// The reference orbit, the LVLH frame and the elliptic relative model (docs/maths.md §32):
// checks 001-U1 (CW limit), U2 (two independent orbit paths, rates against central
// differences) and U3 (the freezing error is second order), Van Loan's Q_d and Γ against
// quadrature, and the z-up range/azimuth/elevation convention.
#include <gtest/gtest.h>

#include <cmath>

#include "hinf/models/elliptic_relative.hpp"
#include "hinf/models/kepler.hpp"
#include "hinf/models/lvlh.hpp"
#include "hinf/models/range_azimuth_elevation.hpp"
#include "hinf/models/two_body.hpp"

namespace {

using hinf::models::kEarthMu;
using hinf::models::kRadiansPerDegree;
using hinf::models::Matrix6;
namespace m = hinf::models;

m::OrbitalElements orbit(double a, double e, double i_deg, double raan_deg, double w_deg, double f_deg) {
  m::OrbitalElements el;
  el.a = a;
  el.e = e;
  el.inclination = i_deg * kRadiansPerDegree;
  el.raan = raan_deg * kRadiansPerDegree;
  el.arg_perigee = w_deg * kRadiansPerDegree;
  el.true_anomaly = f_deg * kRadiansPerDegree;
  return el;
}

// The argument of latitude of a state, measured in the orbit's own plane from r(0).
double angle_from(const m::OrbitState& s0, const m::OrbitState& s) {
  const Eigen::Vector3d x = s0.r.normalized(), z = s0.r.cross(s0.v).normalized(), y = z.cross(x);
  return std::atan2(s.r.dot(y), s.r.dot(x));
}

// 001-U1: for e = 0, A is the CW matrix, and exp(A Δt) the closed-form CW transition.
TEST(EllipticRelative, CircularOrbitGivesTheClohessyWiltshireModelExactly) {
  const m::KeplerOrbit ref(m::state_from_elements(orbit(6678.137e3, 0, 28.5, 45, 0, 315), kEarthMu), kEarthMu);
  const double n = ref.mean_motion();
  EXPECT_NEAR(n, 1.156874e-3, 1e-9);  // the source's chaser
  m::EllipticRelativeModel::Options o;
  const m::EllipticRelativeModel model(ref, o);
  for (double t : {0.0, 1234.5, 5000.0}) {
    const Matrix6 A = model.A(t), Acw = m::clohessy_wiltshire_A(n);
    EXPECT_LE((A - Acw).cwiseAbs().maxCoeff(), 1e-12 * Acw.cwiseAbs().maxCoeff()) << "t = " << t;  // round-off of r, v
    EXPECT_NEAR(A(3, 0), 3 * n * n, 1e-18);
    EXPECT_NEAR(A(3, 0), 4.015069e-6, 1e-12);
  }
  for (double dt : {1.0, 100.0}) {
    const Matrix6 Phi = model.transition(300, dt), closed = m::clohessy_wiltshire_transition(n, dt);
    EXPECT_LE((Phi - closed).cwiseAbs().maxCoeff(), 1e-12) << "dt = " << dt;
  }
}

// 001-U2: the f/g path and the element path agree to 1e-6 m over one orbit, for e = 0.1 at
// three inclinations (0: no node; 98°: retrograde), and the rates match central differences.
TEST(KeplerOrbit, TwoIndependentPathsAgreeOverAnOrbit) {
  for (double inc : {0.0, 28.5, 98.0}) {
    const m::OrbitState s0 = m::state_from_elements(orbit(7000e3, 0.1, inc, 45, 30, 20), kEarthMu);
    const m::KeplerOrbit fg(s0, kEarthMu);
    const m::KeplerElementsPath el(s0, kEarthMu);
    EXPECT_NEAR(fg.eccentricity(), 0.1, 1e-12);
    EXPECT_NEAR(el.eccentricity(), 0.1, 1e-12);
    double worst = 0;
    for (double t = 0; t <= fg.period(); t += fg.period() / 97) {
      const m::OrbitState a = fg.state(t), b = el.state(t);
      worst = std::max(worst, (a.r - b.r).norm());
      EXPECT_LE((a.v - b.v).norm(), 1e-9) << "i = " << inc << ", t = " << t;
    }
    EXPECT_LE(worst, 1e-6) << "i = " << inc;
    // back where it started after a period
    EXPECT_LE((fg.state(fg.period()).r - s0.r).norm(), 1e-6);
  }
}

// Kepler's equation converges at any eccentricity below 1 and after many orbits (the safeguarded
// Newton iteration): the two paths agree at e = 0.7 and 0.97 over 50 orbits, and the state
// returns to itself after each whole period.
TEST(KeplerOrbit, HighEccentricityAndManyOrbitsConverge) {
  for (double e : {0.7, 0.97}) {
    const m::OrbitState s0 = m::state_from_elements(orbit(3e8, e, 40, 10, 250, 170), kEarthMu);
    const m::KeplerOrbit fg(s0, kEarthMu);
    const m::KeplerElementsPath el(s0, kEarthMu);
    for (int k = 0; k < 500; ++k) {
      const double t = fg.period() * (0.1 * k + 0.0123 * (k % 7));
      const m::OrbitState a = fg.state(t), b = el.state(t);
      EXPECT_LE((a.r - b.r).norm(), 1e-6 * a.r.norm()) << "e = " << e << ", t = " << t;
    }
    EXPECT_LE((fg.state(37 * fg.period()).r - s0.r).norm(), 1e-6 * s0.r.norm()) << "e = " << e;
  }
}

TEST(KeplerOrbit, RatesMatchCentralDifferencesOfThePropagatedState) {
  const m::OrbitState s0 = m::state_from_elements(orbit(7000e3, 0.1, 28.5, 45, 30, 20), kEarthMu);
  const m::KeplerOrbit fg(s0, kEarthMu);
  const m::KeplerElementsPath el(s0, kEarthMu);
  const double h = 0.1;
  double max_ddot = 0;
  for (double t = 100; t < fg.period(); t += fg.period() / 23)
    max_ddot = std::max(max_ddot, std::abs(m::orbit_rates(fg.state(t)).theta_ddot));
  EXPECT_GT(max_ddot, 1e-7);  // θ̈ is not negligible on this orbit
  for (double t = 100; t < fg.period(); t += fg.period() / 23) {
    const m::OrbitRates o = m::orbit_rates(fg.state(t));
    double du = angle_from(s0, fg.state(t + h)) - angle_from(s0, fg.state(t - h));
    du = std::remainder(du, 2 * M_PI);
    EXPECT_NEAR(o.theta_dot, du / (2 * h), 1e-7 * o.theta_dot) << "t = " << t;
    const double dd = (m::orbit_rates(fg.state(t + h)).theta_dot - m::orbit_rates(fg.state(t - h)).theta_dot) / (2 * h);
    EXPECT_NEAR(o.theta_ddot, dd, 1e-7 * max_ddot) << "t = " << t;
    // the element path's corrected closed forms, θ̇ = h/r², θ̈ = −2μ e sin f / r³
    EXPECT_NEAR(el.theta_dot(t), o.theta_dot, 1e-12 * o.theta_dot);
    EXPECT_NEAR(el.theta_ddot(t), o.theta_ddot, 1e-9 * max_ddot);
  }
}

TEST(KeplerOrbit, ElementsRoundTripAndRefuseUnboundOrbits) {
  const m::OrbitalElements in = orbit(7000e3, 0.1, 28.5, 45, 30, 20);
  const m::KeplerElementsPath el(m::state_from_elements(in, kEarthMu), kEarthMu);
  EXPECT_NEAR(el.inclination(), in.inclination, 1e-12);
  EXPECT_NEAR(el.raan(), in.raan, 1e-12);
  EXPECT_NEAR(el.arg_perigee(), in.arg_perigee, 1e-9);
  EXPECT_NEAR(el.true_anomaly(0), in.true_anomaly, 1e-9);
  EXPECT_THROW(m::state_from_elements(orbit(7000e3, 1.0, 0, 0, 0, 0), kEarthMu), std::invalid_argument);
  EXPECT_THROW(m::state_from_elements(orbit(-7000e3, 0.1, 0, 0, 0, 0), kEarthMu), std::invalid_argument);
  m::OrbitState escape = m::state_from_elements(in, kEarthMu);
  escape.v *= 1.5;  // above escape speed at this radius
  EXPECT_THROW(m::KeplerOrbit(escape, kEarthMu), std::invalid_argument);
}

// The LVLH basis, its rate, and the relative state against the two-body truth in the frame
// of a circular orbit (two_body.hpp writes the same state in its own rotating frame).
TEST(Lvlh, RelativeStateMatchesTheRotatingFrameOfTheTwoBodyModel) {
  const m::OrbitState ref = m::state_from_elements(orbit(6678.137e3, 0, 28.5, 45, 0, 315), kEarthMu);
  const Eigen::Matrix3d I = m::lvlh_to_inertial(ref);
  EXPECT_LE((I.transpose() * I - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(I.determinant(), 1, 1e-15);
  // a point 1 km radially out and 2 km ahead, moving at 3 m/s along-track in the frame
  const Eigen::Vector3d w = m::lvlh_angular_velocity(ref);
  const Eigen::Vector3d dr = I * Eigen::Vector3d(1000, 2000, -300);
  m::OrbitState target{ref.r + dr, ref.v + w.cross(dr) + I * Eigen::Vector3d(0, 3, 0.5)};
  const Eigen::Matrix<double, 6, 1> X = m::relative_state_in_lvlh(ref, target, ref);
  Eigen::Matrix<double, 6, 1> expected;
  expected << 1000, 2000, -300, 0, 3, 0.5;
  EXPECT_LE((X - expected).cwiseAbs().maxCoeff(), 1e-9);
}

// 001-U3: on the e = 0.1 orbit the velocity rows of exp(A(t_k) Δt) differ from the exact
// transition by ≤ 5e-7 at Δt = 1 s, and the error grows as Δt² (ratio 10 s / 1 s ≈ 100).
TEST(EllipticRelative, FreezingErrorIsSecondOrderInTheSample) {
  const m::KeplerOrbit ref(m::state_from_elements(orbit(7000e3, 0.1, 28.5, 45, 0, 0), kEarthMu), kEarthMu);
  m::EllipticRelativeModel::Options frozen;
  const m::EllipticRelativeModel model(ref, frozen);
  double worst1 = 0, worst10 = 0;
  for (double t = 0; t < ref.period(); t += ref.period() / 37) {
    const auto err = [&](double dt) {
      const Matrix6 exact = model.exact_transition(t, dt, static_cast<int>(std::ceil(dt / 0.01)));
      return (model.transition(t, dt) - exact).bottomRows<3>().cwiseAbs().maxCoeff();
    };
    worst1 = std::max(worst1, err(1));
    worst10 = std::max(worst10, err(10));
  }
  EXPECT_LE(worst1, 5e-7);
  EXPECT_GT(worst1, 1e-9);  // the freezing error exists on this orbit
  EXPECT_GE(worst10 / worst1, 70);
  EXPECT_LE(worst10 / worst1, 130);
  // the midpoint rule is an order better on the same orbit
  m::EllipticRelativeModel::Options mid;
  mid.transition = m::RelativeTransition::FrozenMidpoint;
  const m::EllipticRelativeModel midpoint(ref, mid);
  double worst_mid = 0;
  for (double t = 0; t < ref.period(); t += ref.period() / 37)
    worst_mid = std::max(worst_mid,
                         (midpoint.transition(t, 1) - model.exact_transition(t, 1, 100)).bottomRows<3>().cwiseAbs().maxCoeff());
  EXPECT_LT(worst_mid, worst1 / 10);
}

// Q_d and Γ against trapezoidal quadrature of their integrals, e^{As} from the closed form.
TEST(EllipticRelative, VanLoanNoiseAndHeldInputMatchQuadrature) {
  const m::KeplerOrbit ref(m::state_from_elements(orbit(6678.137e3, 0, 28.5, 45, 0, 315), kEarthMu), kEarthMu);
  m::EllipticRelativeModel::Options o;
  o.process_noise_psd = 0.25;
  const m::EllipticRelativeModel model(ref, o);
  const double dt = 20, n = ref.mean_motion();
  const m::SampledRelativeStep s = model.step(0, dt, true);
  const int N = 20000;
  Matrix6 Q = Matrix6::Zero();
  Eigen::Matrix<double, 6, 3> G = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 6, 3> B = Eigen::Matrix<double, 6, 3>::Zero();
  B.bottomRows<3>().setIdentity();
  for (int i = 0; i <= N; ++i) {
    const double w = (i == 0 || i == N ? 0.5 : 1.0) * dt / N;
    const Matrix6 E = m::clohessy_wiltshire_transition(n, dt * i / N);
    Q += w * 0.25 * E * B * B.transpose() * E.transpose();
    G += w * E * B;
  }
  EXPECT_LE((s.Qd - Q).cwiseAbs().maxCoeff(), 1e-6 * Q.cwiseAbs().maxCoeff());
  EXPECT_LE((s.Gamma - G).cwiseAbs().maxCoeff(), 1e-6 * G.cwiseAbs().maxCoeff());
  EXPECT_LE((s.Qd - s.Qd.transpose()).cwiseAbs().maxCoeff(), 0.0);
}

// The z-up convention: h and its inverse round-trip, the elevation is positive towards +z,
// the Jacobian matches central differences, and z-down is the mirror image.
TEST(RangeAzimuthElevation, ZUpConventionRoundTripsAndDiffersFromZDownBySign) {
  const m::RangeAzimuthElevation up(Eigen::Matrix3d::Identity(), m::ElevationConvention::ZUp);
  const m::RangeAzimuthElevation down;
  Eigen::Matrix<double, 6, 1> x;
  x << 9745.34, 58364.26, 1200.0, 0, 0, 0;
  const auto zu = up.h(x), zd = down.h(x);
  EXPECT_GT(zu(2), 0);
  EXPECT_DOUBLE_EQ(zu(2), -zd(2));
  EXPECT_DOUBLE_EQ(zu(0), zd(0));
  EXPECT_LE((up.position_from_measurement(zu) - x.head<3>()).norm(), 1e-8);
  const auto H = up.H(x);
  for (int j = 0; j < 3; ++j) {
    Eigen::Matrix<double, 6, 1> p = x, q = x;
    p(j) += 1;  // m: the range's rounding (59 km × ε) stays far below the tolerance
    q(j) -= 1;
    const Eigen::Vector3d fd = (up.h(p) - up.h(q)) / 2;
    EXPECT_LE((H.col(j) - fd).cwiseAbs().maxCoeff(), 1e-9) << "column " << j;
  }
  // the conversion Jacobian against central differences of position_from_measurement
  const Eigen::Matrix3d J = up.conversion_jacobian(zu);
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d p = zu, q = zu;
    const double h = j == 0 ? 1e-3 : 1e-8;
    p(j) += h;
    q(j) -= h;
    const Eigen::Vector3d fd = (up.position_from_measurement(p) - up.position_from_measurement(q)) / (2 * h);
    EXPECT_LE((J.col(j) - fd).cwiseAbs().maxCoeff(), 1e-4 * std::max(1.0, J.col(j).norm())) << "column " << j;
  }
}

}  // namespace
