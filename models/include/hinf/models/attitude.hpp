// Rotations: the cross-product matrix, modified Rodrigues parameters (MRP) and the 3-1-2
// Euler angles used to report attitude errors (docs/maths.md §29.1, (179)–(186)).
// Every direction-cosine matrix (DCM) here is *passive*: R_XY maps coordinates in Y to
// coordinates in X, and Ṙ_XY = −[ω×] R_XY with ω the rate of X relative to Y, in X.
// Needs Eigen only.
#pragma once
#include <Eigen/Dense>
#include <cmath>

namespace hinf::models {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180;

// [v×]: the matrix of the cross product, [v×] u = v × u.
inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// R(σ) = I + (8[σ×]² − 4(1 − σᵀσ)[σ×]) / (1 + σᵀσ)², docs/maths.md (179).
inline Eigen::Matrix3d mrp_to_dcm(const Eigen::Vector3d& s) {
  const double s2 = s.squaredNorm();
  const Eigen::Matrix3d S = cross_matrix(s);
  return Eigen::Matrix3d::Identity() + (8 * S * S - 4 * (1 - s2) * S) / ((1 + s2) * (1 + s2));
}

// σ'' with R(σ'') = R(σ') R(σ) (σ applied first), docs/maths.md (180). The result may lie
// outside the unit ball; mrp_canonical picks the short set.
inline Eigen::Vector3d mrp_compose(const Eigen::Vector3d& s_second, const Eigen::Vector3d& s_first) {
  const double a2 = s_second.squaredNorm(), b2 = s_first.squaredNorm();
  return ((1 - b2) * s_second + (1 - a2) * s_first - 2 * s_second.cross(s_first)) /
         (1 + a2 * b2 - 2 * s_second.dot(s_first));
}

// The shadow set σˢ = −σ/|σ|² (same DCM) and its Jacobian ∂σˢ/∂σ = (2σσᵀ − |σ|²I)/|σ|⁴,
// docs/maths.md (181), (182). σ ≠ 0.
inline Eigen::Vector3d mrp_shadow(const Eigen::Vector3d& s) { return -s / s.squaredNorm(); }
inline Eigen::Matrix3d mrp_shadow_jacobian(const Eigen::Vector3d& s) {
  const double s2 = s.squaredNorm();
  return (2 * s * s.transpose() - s2 * Eigen::Matrix3d::Identity()) / (s2 * s2);
}

// σ if |σ| ≤ 1, else its shadow: the set of rotations of at most 180°.
inline Eigen::Vector3d mrp_canonical(const Eigen::Vector3d& s) {
  return s.squaredNorm() > 1 ? mrp_shadow(s) : s;
}

// σ̇ = M(σ) ω for Ṙ(σ) = −[ω×] R(σ): M(σ) = ¼[(1 − σᵀσ) I + 2[σ×] + 2σσᵀ], docs/maths.md (183).
inline Eigen::Matrix3d mrp_kinematics(const Eigen::Vector3d& s) {
  return 0.25 * ((1 - s.squaredNorm()) * Eigen::Matrix3d::Identity() + 2 * cross_matrix(s) + 2 * s * s.transpose());
}

// The MRP of a DCM (|σ| ≤ 1), through the unit quaternion (Eigen's Shepperd-type
// conversion of the active matrix Rᵀ): σ = q_v / (1 + q_w) with q_w ≥ 0, docs/maths.md (184).
inline Eigen::Vector3d mrp_from_dcm(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(Eigen::Matrix3d(R.transpose()));
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return q.vec() / (1 + q.w());
}

// Elementary passive rotations about the axes 1, 2, 3 by the angle a (rad).
inline Eigen::Matrix3d rotation_1(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, c, s, 0, -s, c;
  return m;
}
inline Eigen::Matrix3d rotation_2(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << c, 0, -s, 0, 1, 0, s, 0, c;
  return m;
}
inline Eigen::Matrix3d rotation_3(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << c, s, 0, -s, c, 0, 0, 0, 1;
  return m;
}

// 3-1-2 Euler angles (roll φ, pitch θ, yaw ψ), R = R2(θ) R1(φ) R3(ψ), docs/maths.md (185), (186).
inline Eigen::Matrix3d dcm_from_euler312(const Eigen::Vector3d& roll_pitch_yaw) {
  return rotation_2(roll_pitch_yaw(1)) * rotation_1(roll_pitch_yaw(0)) * rotation_3(roll_pitch_yaw(2));
}
inline Eigen::Vector3d euler312_from_dcm(const Eigen::Matrix3d& R) {
  const double sin_roll = std::fmax(-1.0, std::fmin(1.0, R(1, 2)));
  return {std::asin(sin_roll), std::atan2(-R(0, 2), R(2, 2)), std::atan2(-R(1, 0), R(1, 1))};
}

}  // namespace hinf::models
