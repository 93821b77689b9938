// The manoeuvring_target scenario family (docs/maths.md §32, docs/experiments.md "Seed 001"):
// a chaser tracks a non-cooperative target that fires an unknown manoeuvre, in the frame of
// the chaser's initial Keplerian orbit (LVLH0), with range/azimuth/elevation measured in the
// chaser's current frame (LVLH1), and transient-model manoeuvre estimators side by side on
// one stream. SI units, angles in rad; the defaults are the source's case 6.1
// (configs/scenarios/manoeuvring-target-chaser-free.yaml).
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "hinf/models/elliptic_relative.hpp"
#include "hinf/models/kepler.hpp"
#include "hinf/models/range_azimuth_elevation.hpp"
#include "hinf/models/two_body.hpp"

namespace hinf::sim {

// Thrust of a spacecraft: `accel` (m/s²) from `start` to `end` (s, switched on sample
// boundaries: on over [t_k, t_k + Δt] when start ≤ t_k < end), resolved in the spacecraft's own
// LVLH frame (turning with it) or in LVLH0.
enum class ThrustFrame { OwnLvlh, Lvlh0 };

struct ThrustArc {
  double start = 0, end = 0;
  Eigen::Vector3d accel = Eigen::Vector3d::Zero();
  ThrustFrame frame = ThrustFrame::OwnLvlh;
  bool on(double t_sample) const { return start <= t_sample && t_sample < end; }
};

inline models::OrbitalElements circular_orbit(double a, double inclination, double raan, double true_anomaly) {
  models::OrbitalElements e;
  e.a = a;
  e.inclination = inclination;
  e.raan = raan;
  e.true_anomaly = true_anomaly;
  return e;
}

struct ManoeuvringScenario {
  double duration = 1000;   // s
  double sample_time = 1;   // s (the source gives none)
  int truth_substeps = 10;  // RK4 steps per sample
  double mu = models::kEarthMu;
  double earth_radius = 6378137.0;  // m: an orbit with a ≤ it is refused
  models::OrbitalElements target = circular_orbit(6688.137e3, 28.5 * models::kRadiansPerDegree,
                                                   45 * models::kRadiansPerDegree, 315.5 * models::kRadiansPerDegree);
  models::OrbitalElements chaser = circular_orbit(6678.137e3, 28.5 * models::kRadiansPerDegree,
                                                   45 * models::kRadiansPerDegree, 315 * models::kRadiansPerDegree);
  std::vector<ThrustArc> target_manoeuvres{{300, 600, Eigen::Vector3d(0.5, 0.5, 0), ThrustFrame::OwnLvlh}};
  std::vector<ThrustArc> chaser_manoeuvres;
  double navigation_position_sigma = 0;  // m, the chaser's INS error per axis (ECI)
  double navigation_velocity_sigma = 0;  // m/s
  models::ElevationConvention convention = models::ElevationConvention::ZUp;
  Eigen::Vector3d measurement_sigma{1.0, 1e-3, 1e-3};  // range (m), azimuth, elevation (rad)
  bool noise = true;  // false: no measurement, INS or initial-estimate noise (the mean response)
};

enum class ManoeuvreCovariance { Paper, Innovation, Both };

struct ManoeuvreFilterSettings {
  std::string name = "transient";
  models::EllipticRelativeModel::Options model;  // transition, q, exact substeps
  bool predict_with_chaser_control = false;
  ManoeuvreCovariance covariance = ManoeuvreCovariance::Both;
  int detector_window = 0;            // w; 0: no detector
  double detector_false_alarm = 1e-3; // P_FA of each test
};

// X(t0|t0) = truth + N(0, diag(initial_error_sigma²)) (truth when noise is off), P0 = diag(sigma²).
struct ManoeuvringEstimate {
  Eigen::Matrix<double, 6, 1> initial_error_sigma = (Eigen::Matrix<double, 6, 1>() << 1, 1, 1, 0.1, 0.1, 0.1).finished();
  Eigen::Matrix<double, 6, 1> sigma = (Eigen::Matrix<double, 6, 1>() << 1, 1, 1, 0.1, 0.1, 0.1).finished();
};

// A metric window [start, end): states at t and manoeuvre estimates tagged t with start ≤ t < end.
struct MetricWindow {
  std::string name;
  double start = 0, end = 0;
};

}  // namespace hinf::sim
