// Range, azimuth, elevation of the target (docs/maths.md §10; the paper's eq. 7), and the
// z-up convention of docs/maths.md (222) (ElevationConvention::ZUp: elevation positive towards
// +z, p_z = +rho sin(beta); every sign of beta below flips).
//
// State x = [r; v], r the relative position in the reference (Hill) frame. With C_bl the
// frame-to-body rotation (default identity), the body-frame position is p = C_bl r and
//
//     p = (rho cos(beta) cos(alpha),  rho cos(beta) sin(alpha),  -rho sin(beta))
//
// so h(x) = (rho, alpha, beta) with
//     rho = |p|,  alpha = atan2(p_y, p_x) in (-pi, pi],  beta = atan2(-p_z, hypot(p_x, p_y)).
//
// Jacobian (analytic), with s = p_x^2 + p_y^2, q = sqrt(s):
//     d rho / dp   = p^T / rho
//     d alpha / dp = (-p_y, p_x, 0) / s
//     d beta / dp  = (p_z p_x / (q rho^2), p_z p_y / (q rho^2), -q / rho^2)
//     H = [ (d(rho,alpha,beta)/dp) C_bl , 0_3x3 ].
// h is undefined at rho = 0 and H at q = 0 (target on the body z axis); there the
// results are non-finite and Ekf/Rekf report FilterStatus::ModelNotFinite.
//
// Indirect (Cartesian) use: position r = C_bl^T (rho cb ca, rho cb sa, -rho sb) and the
// first-order covariance of that converted position for independent noises on rho,
// alpha, beta:  Cov = J diag(s_rho^2, s_alpha^2, s_beta^2) J^T, J = d r / d(rho, alpha, beta).
// It depends on the measured point and is generally not diagonal (correlated).
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace hinf::models {

// Which way elevation is positive: towards −z (§10, the default) or towards +z ((222)).
enum class ElevationConvention { ZDown, ZUp };

class RangeAzimuthElevation {
 public:
  static constexpr int NX = 6;
  static constexpr int NZ = 3;
  using State = Eigen::Matrix<double, 6, 1>;
  using Vector = Eigen::Matrix<double, 3, 1>;  // (rho, alpha, beta)
  using Jacobian = Eigen::Matrix<double, 3, 6>;

  // C_bl must be a rotation (orthonormal, det +1, to 1e-9); throws std::invalid_argument.
  explicit RangeAzimuthElevation(const Eigen::Matrix3d& C_bl = Eigen::Matrix3d::Identity(),
                                 ElevationConvention convention = ElevationConvention::ZDown)
      : C_bl_(C_bl), up_(convention == ElevationConvention::ZUp ? 1.0 : -1.0) {
    if (!C_bl.allFinite()) throw std::invalid_argument("RangeAzimuthElevation: C_bl (3x3) has a non-finite entry");
    const double orth = (C_bl * C_bl.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (orth > 1e-9 || C_bl.determinant() < 0.0)
      throw std::invalid_argument("RangeAzimuthElevation: C_bl (3x3) is not a rotation (|C C^T - I|_max = " +
                                  std::to_string(orth) + ", det = " + std::to_string(C_bl.determinant()) + ")");
  }

  // (rho, alpha, beta) of a body-frame position.
  Vector rae_from_body(const Eigen::Vector3d& p) const {
    const double q = std::hypot(p.x(), p.y());
    return Vector(p.norm(), std::atan2(p.y(), p.x()), std::atan2(up_ * p.z(), q));
  }

  Vector h(const State& x) const { return rae_from_body(C_bl_ * x.head<3>()); }

  Jacobian H(const State& x) const {
    const Eigen::Vector3d p = C_bl_ * x.head<3>();
    const double s = p.x() * p.x() + p.y() * p.y();
    const double q = std::sqrt(s);
    const double rho2 = s + p.z() * p.z();
    const double rho = std::sqrt(rho2);
    Eigen::Matrix3d J;
    J.row(0) = p.transpose() / rho;
    J.row(1) << -p.y() / s, p.x() / s, 0.0;
    J.row(2) << -up_ * p.z() * p.x() / (q * rho2), -up_ * p.z() * p.y() / (q * rho2), up_ * q / rho2;
    Jacobian Hk;
    Hk << J * C_bl_, Eigen::Matrix3d::Zero();
    return Hk;
  }

  // y - y_pred with the azimuth difference wrapped to (-pi, pi].
  Vector residual(const Vector& y, const Vector& y_pred) const {
    Vector d = y - y_pred;
    d(1) = wrap_pi(d(1));
    return d;
  }

  // Inverse of h: reference-frame position from (rho, alpha, beta).
  Eigen::Vector3d position_from_measurement(const Vector& y) const {
    const double rho = y(0), ca = std::cos(y(1)), sa = std::sin(y(1)), cb = std::cos(y(2)), sb = std::sin(y(2));
    return C_bl_.transpose() * Eigen::Vector3d(rho * cb * ca, rho * cb * sa, up_ * rho * sb);
  }

  // d position / d(rho, alpha, beta) at y.
  Eigen::Matrix3d conversion_jacobian(const Vector& y) const {
    const double rho = y(0), ca = std::cos(y(1)), sa = std::sin(y(1)), cb = std::cos(y(2)), sb = std::sin(y(2));
    Eigen::Matrix3d Jg;
    Jg.col(0) << cb * ca, cb * sa, up_ * sb;
    Jg.col(1) << -rho * cb * sa, rho * cb * ca, 0.0;
    Jg.col(2) << -rho * sb * ca, -rho * sb * sa, up_ * rho * cb;
    return C_bl_.transpose() * Jg;
  }

  // First-order covariance of position_from_measurement(y) for independent noises with
  // standard deviations sigma_rho (m), sigma_alpha, sigma_beta (rad).
  Eigen::Matrix3d position_covariance(const Vector& y, double sigma_rho, double sigma_alpha, double sigma_beta) const {
    return covariance_through(conversion_jacobian(y), sigma_rho, sigma_alpha, sigma_beta);
  }
  // The same with J = conversion_jacobian(y) at hand (computed once for several filters).
  static Eigen::Matrix3d covariance_through(const Eigen::Matrix3d& J, double sigma_rho, double sigma_alpha,
                                            double sigma_beta) {
    const Eigen::Vector3d var(sigma_rho * sigma_rho, sigma_alpha * sigma_alpha, sigma_beta * sigma_beta);
    Eigen::Matrix3d Cov = J * var.asDiagonal() * J.transpose();
    return 0.5 * (Cov + Cov.transpose());
  }

  const Eigen::Matrix3d& C_bl() const { return C_bl_; }

  static double wrap_pi(double a) {
    const double two_pi = 2.0 * 3.14159265358979323846;
    a = std::remainder(a, two_pi);  // in [-pi, pi]
    if (a <= -3.14159265358979323846) a += two_pi;
    return a;
  }

 private:
  Eigen::Matrix3d C_bl_;
  double up_;  // +1 for ZUp, −1 for ZDown
};

}  // namespace hinf::models
