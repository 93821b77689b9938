// The truth of the manoeuvring_target family (docs/maths.md §32.4): target and chaser as two
// point masses in ECI under two-body gravity and their thrust arcs, integrated by RK4, and
// the reference point R flying the chaser's initial Keplerian orbit.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "hinf/models/kepler.hpp"
#include "hinf/sim/manoeuvring_scenario.hpp"

namespace hinf::sim {

struct ManoeuvringTruthSample {
  double t = 0;
  models::OrbitState target, chaser, reference;  // ECI at t
  Eigen::Matrix<double, 6, 1> relative;          // X of the target from the chaser in LVLH0, (218)
  // The thrust accelerations over [t, t + Δt] in LVLH0, averaged with RK4's weights (the
  // average the velocity integrates); zero at the last sample.
  Eigen::Vector3d target_accel = Eigen::Vector3d::Zero(), chaser_accel = Eigen::Vector3d::Zero();
};

// The thrust (ECI, m/s²) of `arcs` on a spacecraft at `own` during the sample starting at
// t_sample, with I0 the LVLH0 → ECI rotation at that instant.
Eigen::Vector3d thrust_inertial(const std::vector<ThrustArc>& arcs, double t_sample, const models::OrbitState& own,
                                const Eigen::Matrix3d& I0);

// The samples t_k = k Δt, k = 0 … N. The orbits must be elliptic (the scenario reader checks
// them; models::state_from_elements throws std::invalid_argument otherwise).
std::vector<ManoeuvringTruthSample> manoeuvring_truth(const ManoeuvringScenario& s);

}  // namespace hinf::sim
