// Extended Kalman filter, generic over the process model and the measurement model.
//
// Model requirements (see models/hill.hpp, models/linear.hpp):
//   static constexpr int NX, NU;  types State (NX x 1), Input (NU x 1)
//   State f(const State& x, const Input& u) const;        x(k+1) = f(x(k), u(k))
//   F(const State& x, const Input& u) const -> NX x NX     Jacobian of f
// Measurement requirements (models/cartesian_position.hpp, models/range_azimuth_elevation.hpp):
//   static constexpr int NX, NZ;  type Vector (NZ x 1)
//   Vector h(const State& x) const;  H(const State& x) const -> NZ x NX;
//   Vector residual(const Vector& y, const Vector& y_pred) const;   (e.g. angle wrapping)
//
//   predict(u):  x = f(x, u),  P = F P F^T + Q                      (symmetrised)
//   update(y):   nu = residual(y, h(x)),  S = H P H^T + R,  K = P H^T S^-1,
//                x = x + K nu,  P = (I - K H) P (I - K H)^T + K R K^T  (Joseph, symmetrised)
// S is factored by Cholesky (LLT); no explicit inverse. The normalised innovation squared
// nis() = nu^T S^-1 nu is kept for consistency monitoring and can gate updates.
// Failures are reported as FilterStatus; the policy is documented in filter_status.hpp.
// Fixed sizes throughout: no heap allocation in predict()/update().
#pragma once

#include <Eigen/Dense>

#include <limits>
#include <stdexcept>

#include "hinf/runtime/detail/covariance.hpp"
#include "hinf/runtime/detail/joseph_update.hpp"
#include "hinf/runtime/filter_status.hpp"

namespace hinf::runtime {

template <class Model, class Measurement>
class Ekf {
 public:
  static constexpr int NX = Model::NX;
  static constexpr int NU = Model::NU;
  static constexpr int NZ = Measurement::NZ;
  static_assert(NX > 0 && NU > 0 && NZ > 0, "Ekf: dimensions must be positive");
  static_assert(Measurement::NX == Model::NX, "Ekf: model and measurement state dimensions differ");

  using State = Eigen::Matrix<double, NX, 1>;
  using Input = Eigen::Matrix<double, NU, 1>;
  using Observation = Eigen::Matrix<double, NZ, 1>;
  using StateCov = Eigen::Matrix<double, NX, NX>;
  using ObsCov = Eigen::Matrix<double, NZ, NZ>;
  using Gain = Eigen::Matrix<double, NX, NZ>;

  // Q symmetric positive semidefinite, R symmetric positive definite; throws
  // std::invalid_argument otherwise. Call init() before the first step.
  Ekf(const Model& model, const Measurement& measurement, const StateCov& Q, const ObsCov& R)
      : model_(model), meas_(measurement) {
    set_Q(Q);
    set_R(R);
    x_.setZero();
    P_.setIdentity();
    P0_.setIdentity();
    K_.setZero();
    S_.setZero();
    nu_.setZero();
  }

  // x(0) and P(0); P0 (symmetric PD, else std::invalid_argument) is also the reset value.
  void init(const State& x0, const StateCov& P0) {
    if (!x0.allFinite()) throw std::invalid_argument("Ekf: x0 has a non-finite entry");
    detail::require_positive_definite(P0, "Ekf", "P0");
    x_ = x0;
    P0_ = 0.5 * (P0 + P0.transpose());
    P_ = P0_;
  }

  FilterStatus predict(const Input& u) {
    if (!u.allFinite()) return FilterStatus::NonFiniteInput;
    const State x_next = model_.f(x_, u);
    const StateCov F = model_.F(x_, u);
    if (!x_next.allFinite() || !F.allFinite()) return FilterStatus::ModelNotFinite;
    const StateCov FP = F * P_;
    P_.noalias() = FP * F.transpose();
    P_ += Q_;
    detail::symmetrise(P_);
    x_ = x_next;
    return detail::apply_covariance_policy<NX>(P_, P0_, policy_);
  }

  FilterStatus update(const Observation& y) {
    if (!y.allFinite()) return FilterStatus::NonFiniteInput;
    const Observation y_pred = meas_.h(x_);
    const Eigen::Matrix<double, NZ, NX> H = meas_.H(x_);
    if (!y_pred.allFinite() || !H.allFinite()) return FilterStatus::ModelNotFinite;
    nu_ = meas_.residual(y, y_pred);
    const StateCov P_prior = P_;
    const FilterStatus s = detail::joseph_update<NX, NZ>(x_, P_, P_prior, H, R_, nu_, nis_gate_, nis_, S_, K_);
    if (s != FilterStatus::Ok) return s;
    return detail::apply_covariance_policy<NX>(P_, P0_, policy_);
  }

  // Configuration.
  void set_Q(const StateCov& Q) {
    detail::require_positive_semidefinite(Q, "Ekf", "Q");
    Q_ = 0.5 * (Q + Q.transpose());
  }
  void set_R(const ObsCov& R) {
    detail::require_positive_definite(R, "Ekf", "R");
    R_ = 0.5 * (R + R.transpose());
  }
  void set_covariance_policy(CovariancePolicy p) { policy_ = p; }
  // Reject updates whose NIS exceeds the threshold (e.g. a chi-square quantile with NZ
  // degrees of freedom). Default +infinity: no gating.
  void set_innovation_gate(double nis_threshold) { nis_gate_ = nis_threshold; }
  // Overwrite the state (e.g. after an external reset); P is not checked here.
  void set_state(const State& x, const StateCov& P) {
    x_ = x;
    P_ = P;
  }

  const State& x() const { return x_; }
  const StateCov& P() const { return P_; }
  const StateCov& P0() const { return P0_; }
  const StateCov& Q() const { return Q_; }
  const ObsCov& R() const { return R_; }
  const Gain& K() const { return K_; }             // gain of the last successful update
  const ObsCov& S() const { return S_; }           // innovation covariance of the last update
  const Observation& innovation() const { return nu_; }
  double nis() const { return nis_; }              // nu^T S^-1 nu of the last update
  const Model& model() const { return model_; }
  const Measurement& measurement() const { return meas_; }

 private:
  Model model_;
  Measurement meas_;
  State x_;
  StateCov P_, P0_, Q_;
  ObsCov R_, S_;
  Gain K_;
  Observation nu_;
  double nis_ = 0.0;
  double nis_gate_ = std::numeric_limits<double>::infinity();
  CovariancePolicy policy_ = CovariancePolicy::Report;
};

}  // namespace hinf::runtime
