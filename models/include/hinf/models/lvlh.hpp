// The local-vertical local-horizontal (LVLH) frame of an orbiting point and the relative
// state resolved in it (docs/maths.md §32.2). Header-only, Eigen only.
//
//   x̂ = r/|r| (radial), ẑ = (r × v)/|r × v| (orbit normal), ŷ = ẑ × x̂,   I = [x̂ ŷ ẑ]   (216)
//   (I maps LVLH components to ECI); the frame turns at w = (r × v)/|r|²,
//   θ̇ = |r × v|/|r|²,   θ̈ = −2 θ̇ (r·v)/|r|²                                           (217)
//   relative state of point T from point C in the frame of O:
//   X = [ Iᵀ (r_T − r_C);  Iᵀ ((v_T − v_C) − w × (r_T − r_C)) ]                        (218)
#pragma once
#include <Eigen/Dense>

#include "hinf/models/kepler.hpp"

namespace hinf::models {

// (216)
inline Eigen::Matrix3d lvlh_to_inertial(const OrbitState& s) {
  const Eigen::Vector3d x = s.r.normalized();
  const Eigen::Vector3d z = s.r.cross(s.v).normalized();
  Eigen::Matrix3d I;
  I << x, z.cross(x), z;
  return I;
}

// (217): the rates that drive the elliptic relative model (elliptic_relative.hpp).
struct OrbitRates {
  double radius = 0;      // |r|, m
  double theta_dot = 0;   // rad/s
  double theta_ddot = 0;  // rad/s²
};

inline OrbitRates orbit_rates(const OrbitState& s) {
  const double r2 = s.r.squaredNorm();
  OrbitRates o;
  o.radius = std::sqrt(r2);
  o.theta_dot = s.r.cross(s.v).norm() / r2;
  o.theta_ddot = -2 * o.theta_dot * s.r.dot(s.v) / r2;
  return o;
}

inline Eigen::Vector3d lvlh_angular_velocity(const OrbitState& s) { return s.r.cross(s.v) / s.r.squaredNorm(); }

// (218)
inline Eigen::Matrix<double, 6, 1> relative_state_in_lvlh(const OrbitState& frame, const OrbitState& target,
                                                          const OrbitState& chaser) {
  const Eigen::Matrix3d I = lvlh_to_inertial(frame);
  const Eigen::Vector3d dr = target.r - chaser.r;
  const Eigen::Vector3d dv = target.v - chaser.v - lvlh_angular_velocity(frame).cross(dr);
  Eigen::Matrix<double, 6, 1> X;
  X << I.transpose() * dr, I.transpose() * dv;
  return X;
}

}  // namespace hinf::models
