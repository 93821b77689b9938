// The gps_ins_relative scenario family (docs/maths.md §29, §30): a chaser flying a circle
// around a target on a circular orbit, its attitude held by a PD law, a gyro, GPS
// pseudorange single differences and carrier-phase differences between three antennas.
// Every field in SI units (rad, rad/s, m, N m); the defaults are the fly-around of
// configs/scenarios/gps-ins-flyaround.yaml.
#pragma once
#include <Eigen/Dense>

#include <array>
#include <vector>

#include "hinf/models/attitude.hpp"
#include "hinf/models/gps_ins.hpp"
#include "hinf/models/two_body.hpp"

namespace hinf::sim {

enum class GpsInsTruthDynamics { Nonlinear, Cw };
enum class AttitudeControlLaw { PdFeedforward, None };

struct GpsInsScenario {
  double duration = 10000;  // s
  double sample_time = 1;   // s
  int truth_substeps = 4;   // RK4 steps per sample

  // target orbit (circular)
  double orbit_radius = 6899807;  // m
  double mu = models::kEarthMu;
  double inclination = 45 * models::kRadiansPerDegree;
  double raan = 0;
  double arg_lat0 = 0;
  GpsInsTruthDynamics truth_dynamics = GpsInsTruthDynamics::Nonlinear;

  // relative translation (LVLH)
  Eigen::Vector3d initial_position{100.0, 0.0, -173.21};
  bool initial_velocity_drift_free = true;  // ẏ(0) = −2 n x(0), docs/maths.md §30.1
  Eigen::Vector3d initial_velocity{0, 0.22, 0};  // used when not drift-free (as printed)
  double accel_sigma = 1e-6;  // m/s², per axis, held over Δt

  // chaser attitude
  Eigen::Vector3d initial_euler312{2 * models::kRadiansPerDegree, 3 * models::kRadiansPerDegree,
                                   5 * models::kRadiansPerDegree};  // roll, pitch, yaw of B relative to F
  Eigen::Vector3d initial_rate = Eigen::Vector3d::Zero();  // ω(0), B relative to F, rad/s
  Eigen::Vector3d inertia_nominal{1000, 1200, 900};        // principal moments, kg m²
  double inertia_products_fraction = 0;                    // p
  Eigen::Vector3d inertia_products_signs{1, -1, 1};        // s12, s13, s23
  double torque_sigma = 1e-6;                              // N m, per axis, held over Δt
  AttitudeControlLaw control = AttitudeControlLaw::PdFeedforward;
  double kp = 2.5, kd = 70;  // N m, N m s

  // gyro
  double gyro_noise_sigma = 0.05 / 3600 * models::kRadiansPerDegree;  // rad/s per sample
  Eigen::Vector3d gyro_bias_initial = Eigen::Vector3d::Constant(5.0 / 3600 * models::kRadiansPerDegree);
  double gyro_bias_walk_sigma = 0.03 / 3600 * models::kRadiansPerDegree / 60;  // rad/s^1.5

  // GPS: satellites fixed in LVLH (elevation above the y–z plane, azimuth from +y to +z)
  std::array<Eigen::Vector2d, models::kGpsInsSatellites> satellites_el_az{
      Eigen::Vector2d(90, 0) * models::kRadiansPerDegree, Eigen::Vector2d(30, 0) * models::kRadiansPerDegree,
      Eigen::Vector2d(30, 120) * models::kRadiansPerDegree, Eigen::Vector2d(30, 240) * models::kRadiansPerDegree};
  double satellite_distance = 2.0e7;  // m from the target
  double carrier_frequency = 1575.42e6;
  double pseudorange_sigma = 1.0;  // m, on the single difference
  double phase_sigma = 0.0028;     // cycles, per row
  // The filters' phase rows: the between-antenna differences as simulated, or their double
  // differences against satellite 0 with the correlated covariance (docs/maths.md (193a)).
  enum class PhaseMode { SingleDifference, DoubleDifference } phase_mode = PhaseMode::SingleDifference;
  std::array<Eigen::Vector3d, 3> antennas{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0),
                                          Eigen::Vector3d(0, 2, 0)};  // in B, m

  double orbit_rate() const { return std::sqrt(mu / (orbit_radius * orbit_radius * orbit_radius)); }
  double flyaround_rate() const { return orbit_rate(); }
  Eigen::Vector3d initial_velocity_used() const;
  // R_FR(0): x_F along ρ(0), z_F along ρ(0) × ρ̇(0), y_F = z_F × x_F (docs/maths.md §30.1).
  Eigen::Matrix3d flyaround_frame() const;
  // R_RI(0) = R3(u0) R1(i) R3(Ω).
  Eigen::Matrix3d lvlh_from_inertial0() const;
  // J_true = J_nom + ΔJ, ΔJ_ij = p s_ij sqrt(J_ii J_jj) (docs/maths.md §30.2).
  Eigen::Matrix3d inertia_true() const;
  Eigen::Matrix3d inertia_nominal_matrix() const { return inertia_nominal.asDiagonal(); }
  // b12, b13, b23 in B.
  std::array<Eigen::Vector3d, 3> baselines() const;
  // The satellites' offsets from the target in LVLH, m.
  std::array<Eigen::Vector3d, models::kGpsInsSatellites> satellite_offsets() const;
  // The filter model's parameters (nominal inertia) for `jacobian`.
  models::GpsInsParameters model_parameters(models::GpsInsJacobian jacobian) const;
};

}  // namespace hinf::sim
