// manoeuvring_truth (manoeuvring_truth.hpp).
#include "hinf/sim/manoeuvring_truth.hpp"

#include <cmath>

#include "hinf/models/lvlh.hpp"
#include "hinf/sim/simulation_error.hpp"

namespace hinf::sim {

namespace {

using models::OrbitState;

struct Derivative {
  Eigen::Vector3d dr, dv, thrust;
};

// ṙ = v, v̇ = −μ r/|r|³ + thrust.
Derivative derivative(const ManoeuvringScenario& s, const std::vector<ThrustArc>& arcs, double t_sample,
                      const models::KeplerOrbit& reference, double t, const OrbitState& x) {
  const Eigen::Matrix3d I0 = models::lvlh_to_inertial(reference.state(t));
  const double r = x.r.norm();
  Derivative d;
  d.thrust = thrust_inertial(arcs, t_sample, x, I0);
  d.dr = x.v;
  d.dv = -s.mu / (r * r * r) * x.r + d.thrust;
  return d;
}

OrbitState advanced(const OrbitState& x, const Derivative& d, double h) { return {x.r + h * d.dr, x.v + h * d.dv}; }

// One sample of one spacecraft by RK4; `mean_thrust` gets its RK4-weighted mean in LVLH0.
OrbitState propagate(const ManoeuvringScenario& s, const std::vector<ThrustArc>& arcs,
                     const models::KeplerOrbit& reference, double t_sample, OrbitState x,
                     Eigen::Vector3d& mean_thrust) {
  const double h = s.sample_time / s.truth_substeps;
  mean_thrust.setZero();
  const auto lvlh0 = [&](double t, const Eigen::Vector3d& a) -> Eigen::Vector3d {
    return models::lvlh_to_inertial(reference.state(t)).transpose() * a;
  };
  for (int j = 0; j < s.truth_substeps; ++j) {
    const double t = t_sample + j * h;
    const Derivative k1 = derivative(s, arcs, t_sample, reference, t, x);
    const Derivative k2 = derivative(s, arcs, t_sample, reference, t + h / 2, advanced(x, k1, h / 2));
    const Derivative k3 = derivative(s, arcs, t_sample, reference, t + h / 2, advanced(x, k2, h / 2));
    const Derivative k4 = derivative(s, arcs, t_sample, reference, t + h, advanced(x, k3, h));
    x.r += h / 6 * (k1.dr + 2 * k2.dr + 2 * k3.dr + k4.dr);
    x.v += h / 6 * (k1.dv + 2 * k2.dv + 2 * k3.dv + k4.dv);
    mean_thrust += (lvlh0(t, k1.thrust) + 2 * lvlh0(t + h / 2, k2.thrust) + 2 * lvlh0(t + h / 2, k3.thrust) +
                    lvlh0(t + h, k4.thrust)) /
                   (6.0 * s.truth_substeps);
  }
  return x;
}

}  // namespace

Eigen::Vector3d thrust_inertial(const std::vector<ThrustArc>& arcs, double t_sample, const OrbitState& own,
                                const Eigen::Matrix3d& I0) {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (const ThrustArc& arc : arcs) {
    if (!arc.on(t_sample)) continue;
    a += (arc.frame == ThrustFrame::OwnLvlh ? models::lvlh_to_inertial(own) : I0) * arc.accel;
  }
  return a;
}

std::vector<ManoeuvringTruthSample> manoeuvring_truth(const ManoeuvringScenario& s) {
  OrbitState target = models::state_from_elements(s.target, s.mu);
  OrbitState chaser = models::state_from_elements(s.chaser, s.mu);
  const models::KeplerOrbit reference(chaser, s.mu);
  const long n = std::lround(s.duration / s.sample_time);
  std::vector<ManoeuvringTruthSample> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  for (long k = 0; k <= n; ++k) {
    ManoeuvringTruthSample x;
    x.t = static_cast<double>(k) * s.sample_time;
    x.target = target;
    x.chaser = chaser;
    x.reference = reference.state(x.t);
    x.relative = models::relative_state_in_lvlh(x.reference, target, chaser);
    Eigen::Matrix<double, 18, 1> all;
    all << target.r, target.v, chaser.r, chaser.v, x.relative;
    require_finite_truth("manoeuvring_target", k, x.t, all,
                         {{"target position (ECI, m)", 0, 3},
                          {"target velocity (ECI, m/s)", 3, 3},
                          {"chaser position (ECI, m)", 6, 3},
                          {"chaser velocity (ECI, m/s)", 9, 3},
                          {"relative state in LVLH0", 12, 6}});
    if (k < n) {
      target = propagate(s, s.target_manoeuvres, reference, x.t, target, x.target_accel);
      chaser = propagate(s, s.chaser_manoeuvres, reference, x.t, chaser, x.chaser_accel);
    }
    out.push_back(x);
  }
  return out;
}

}  // namespace hinf::sim
