// The unperturbed two-body (Keplerian) orbit of a point mass about the Earth, for elliptic
// orbits 0 ≤ e < 1 (docs/maths.md §32.1). Header-only, Eigen only.
//
//   state_from_elements: classical elements → (r, v) in ECI, (213).
//   KeplerOrbit:         (r0, v0) → (r, v) at t0 + Δt by Lagrange's f and g with the
//                        difference of eccentric anomaly ΔE, (214). No singularity at e = 0
//                        or i = 0: nothing but r0, v0 and a enter.
//   KeplerElementsPath:  the same orbit through the elements (a, e, i, Ω, ω, M0), (215): the
//                        path of the source, kept as an independent check of KeplerOrbit.
#pragma once
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "hinf/models/attitude.hpp"

namespace hinf::models {

struct OrbitState {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  // m, ECI
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  // m/s, ECI
};

// Classical elements; angles in rad.
struct OrbitalElements {
  double a = 0;            // semi-major axis, m
  double e = 0;            // eccentricity, [0, 1)
  double inclination = 0;  // i
  double raan = 0;         // Ω
  double arg_perigee = 0;  // ω
  double true_anomaly = 0; // f
};

namespace detail {
constexpr double kKeplerTolerance = 1e-14;  // the Newton step (rad) at which Kepler's equations stop
constexpr int kKeplerMaxIterations = 100;
constexpr double kCircularEccentricity = 1e-10;  // below it the anomalies are the argument of latitude
constexpr double kTwoPi = 2 * 3.14159265358979323846;

// The root of an increasing g in [lo, hi] (g(lo) ≤ 0 ≤ g(hi)) by Newton from x0, a step that
// would leave the bracket replaced by bisection, so that it converges for every e < 1.
template <class G, class DG>
double increasing_root(const G& g, const DG& dg, double lo, double hi, double x0) {
  double x = x0;
  for (int i = 0; i < kKeplerMaxIterations; ++i) {
    const double gx = g(x);
    if (gx == 0) return x;
    if (gx < 0)
      lo = x;
    else
      hi = x;
    const double newton = x - gx / dg(x);
    if (std::abs(newton - x) < kKeplerTolerance * std::max(1.0, std::abs(x))) return newton;
    x = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
  }
  return x;
}

// The E with E − e sin E = M (|E − M| ≤ e < 1 brackets it).
inline double solve_kepler(double M, double e) {
  return increasing_root([&](double E) { return E - e * std::sin(E) - M; },
                         [&](double E) { return 1 - e * std::cos(E); }, M - 1, M + 1, M);
}

// The true anomaly from the eccentric one, by the half-angle atan2 form.
inline double true_from_eccentric(double E, double e) {
  return 2 * std::atan2(std::sqrt(1 + e) * std::sin(E / 2), std::sqrt(1 - e) * std::cos(E / 2));
}
}  // namespace detail

// (213): perifocal position and velocity rotated by R3(Ω) R1(i) R3(ω). Throws
// std::invalid_argument naming the element for e ∉ [0, 1), a ≤ 0 or a non-finite entry.
inline OrbitState state_from_elements(const OrbitalElements& el, double mu) {
  if (!(el.a > 0) || !std::isfinite(el.a)) throw std::invalid_argument("a: must be a finite number > 0");
  if (!(el.e >= 0 && el.e < 1)) throw std::invalid_argument("e: must be in [0, 1) (elliptic orbits only)");
  const double p = el.a * (1 - el.e * el.e);
  const double cf = std::cos(el.true_anomaly), sf = std::sin(el.true_anomaly);
  const double r = p / (1 + el.e * cf);
  const Eigen::Matrix3d R = rotation_3(-el.raan) * rotation_1(-el.inclination) * rotation_3(-el.arg_perigee);
  OrbitState s;
  s.r = R * Eigen::Vector3d(r * cf, r * sf, 0);
  s.v = R * (std::sqrt(mu / p) * Eigen::Vector3d(-sf, el.e + cf, 0));
  if (!s.r.allFinite() || !s.v.allFinite()) throw std::invalid_argument("orbit elements: non-finite state");
  return s;
}

// (214). Throws std::invalid_argument if (r0, v0) is not a bound orbit.
class KeplerOrbit {
 public:
  KeplerOrbit(const OrbitState& s0, double mu) : s0_(s0), mu_(mu) {
    r0_ = s0.r.norm();
    const double inv_a = 2 / r0_ - s0.v.squaredNorm() / mu;
    if (!(inv_a > 0) || !std::isfinite(inv_a))
      throw std::invalid_argument("orbit: not elliptic (2/|r| − |v|²/μ = " + std::to_string(inv_a) + " 1/m)");
    a_ = 1 / inv_a;
    n_ = std::sqrt(mu / (a_ * a_ * a_));
    e_cos_E0_ = 1 - r0_ / a_;
    e_sin_E0_ = s0.r.dot(s0.v) / std::sqrt(mu * a_);
  }

  OrbitState state(double dt) const {
    const double dE = eccentric_anomaly_change(dt);
    const double c = std::cos(dE), s = std::sin(dE);
    const double r = a_ + (r0_ - a_) * c + a_ * e_sin_E0_ * s;
    const double f = 1 - a_ / r0_ * (1 - c);
    const double g = dt + (s - dE) / n_;
    const double fdot = -std::sqrt(mu_ * a_) * s / (r * r0_);
    const double gdot = 1 - a_ / r * (1 - c);
    return {f * s0_.r + g * s0_.v, fdot * s0_.r + gdot * s0_.v};
  }

  double semi_major_axis() const { return a_; }
  double eccentricity() const { return std::hypot(e_cos_E0_, e_sin_E0_); }
  double mean_motion() const { return n_; }
  double period() const { return detail::kTwoPi / n_; }
  double mu() const { return mu_; }
  const OrbitState& initial_state() const { return s0_; }

 private:
  // n Δt = ΔE − e cos E0 sin ΔE + e sin E0 (1 − cos ΔE): whole orbits taken out first, the rest
  // (|ΔE − M| ≤ 3e < 3) by the safeguarded Newton iteration (the derivative is r/a > 0).
  double eccentric_anomaly_change(double dt) const {
    const double M = n_ * dt;
    const double turns = std::floor(M / detail::kTwoPi);
    const double m = M - turns * detail::kTwoPi;
    const double dE = detail::increasing_root(
        [&](double x) { return x - e_cos_E0_ * std::sin(x) + e_sin_E0_ * (1 - std::cos(x)) - m; },
        [&](double x) { return 1 - e_cos_E0_ * std::cos(x) + e_sin_E0_ * std::sin(x); }, m - 3, m + 3, m);
    return dE + turns * detail::kTwoPi;
  }

  OrbitState s0_;
  double mu_, r0_, a_, n_, e_cos_E0_, e_sin_E0_;
};

// (215): the elements of (r0, v0) (with the source's formulas corrected: r⃗·v⃗ a dot product,
// atan2 throughout, the argument of latitude measured from the node without dividing by sin i,
// Ω = 0 for an equatorial orbit, ω = 0 for a circular one), then Kepler's equation at every t.
class KeplerElementsPath {
 public:
  KeplerElementsPath(const OrbitState& s0, double mu) : mu_(mu) {
    const double r0 = s0.r.norm();
    a_ = 1 / (2 / r0 - s0.v.squaredNorm() / mu);
    if (!(a_ > 0) || !std::isfinite(a_)) throw std::invalid_argument("orbit: not elliptic");
    n_ = std::sqrt(mu / (a_ * a_ * a_));
    const double sigma0 = s0.r.dot(s0.v) / std::sqrt(mu * a_);
    e_ = std::hypot(sigma0, 1 - r0 / a_);
    const Eigen::Vector3d h = s0.r.cross(s0.v);
    const double hxy = std::hypot(h.x(), h.y());
    raan_ = hxy > 1e-12 * h.norm() ? std::atan2(h.x(), -h.y()) : 0.0;
    inclination_ = std::atan2(hxy, h.z());
    const Eigen::Vector3d node(std::cos(raan_), std::sin(raan_), 0);
    const double u0 = std::atan2(s0.r.dot(h.normalized().cross(node)), s0.r.dot(node));
    if (e_ < detail::kCircularEccentricity) {
      e_ = 0;
      arg_perigee_ = 0;
      M0_ = u0;
    } else {
      const double E0 = std::atan2(sigma0, 1 - r0 / a_);
      M0_ = E0 - e_ * std::sin(E0);
      arg_perigee_ = u0 - detail::true_from_eccentric(E0, e_);
    }
  }

  double true_anomaly(double dt) const {
    const double M = M0_ + n_ * dt;
    return e_ == 0 ? M : detail::true_from_eccentric(detail::solve_kepler(std::remainder(M, detail::kTwoPi), e_), e_);
  }

  OrbitState state(double dt) const {
    const double f = true_anomaly(dt);
    const double p = a_ * (1 - e_ * e_);
    const double r = p / (1 + e_ * std::cos(f));
    const Eigen::Matrix3d I = lvlh_to_inertial(f);
    const double rdot = std::sqrt(mu_ / p) * e_ * std::sin(f);
    const double rtheta_dot = std::sqrt(mu_ * p) / r;
    return {r * I.col(0), rdot * I.col(0) + rtheta_dot * I.col(1)};
  }

  // θ̇ = h/r² and θ̈ = −2μ e sin f / r³ (the source's two printed forms corrected).
  double theta_dot(double dt) const {
    const double f = true_anomaly(dt), p = a_ * (1 - e_ * e_), r = p / (1 + e_ * std::cos(f));
    return std::sqrt(mu_ * p) / (r * r);
  }
  double theta_ddot(double dt) const {
    const double f = true_anomaly(dt), p = a_ * (1 - e_ * e_), r = p / (1 + e_ * std::cos(f));
    return -2 * mu_ * e_ * std::sin(f) / (r * r * r);
  }

  // I0 = R3(Ω) R1(i) R3(ω + f): LVLH components → ECI.
  Eigen::Matrix3d lvlh_to_inertial(double f) const {
    return rotation_3(-raan_) * rotation_1(-inclination_) * rotation_3(-(arg_perigee_ + f));
  }

  double eccentricity() const { return e_; }
  double inclination() const { return inclination_; }
  double raan() const { return raan_; }
  double arg_perigee() const { return arg_perigee_; }

 private:
  double mu_, a_, n_, e_, raan_, inclination_, arg_perigee_, M0_;
};

}  // namespace hinf::models
