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

#include "hinf/runtime/detail/kalman_core.hpp"
#include "hinf/runtime/filter_status.hpp"

namespace hinf::runtime {

template <class Model, class Measurement>
class Ekf : public detail::KalmanCore<Model, Measurement> {
  using Core = detail::KalmanCore<Model, Measurement>;

 public:
  using typename Core::Input;
  using typename Core::MeasurementJacobian;
  using typename Core::ObsCov;
  using typename Core::Observation;
  using typename Core::State;
  using typename Core::StateCov;

  // Q symmetric positive semidefinite, R symmetric positive definite; throws
  // std::invalid_argument otherwise. Call init() before the first step.
  Ekf(const Model& model, const Measurement& measurement, const StateCov& Q, const ObsCov& R)
      : Core(model, measurement, Q, R, "Ekf") {}

  // docs/maths.md (88): x = f(x, u), P = F P Fᵀ + Q.
  FilterStatus predict(const Input& u) {
    State x_next;
    StateCov F;
    const FilterStatus s = this->evaluate_process(u, x_next, F);
    if (s != FilterStatus::Ok) return s;
    return this->finish_predict(x_next, F, this->P_, nullptr);  // F·P is formed before P is written
  }

  // docs/maths.md (89)–(91): the Joseph update from P with R.
  FilterStatus update(const Observation& y) {
    Observation y_pred;
    MeasurementJacobian H;
    const FilterStatus s = this->evaluate_measurement(y, y_pred, H);
    if (s != FilterStatus::Ok) return s;
    const StateCov P_prior = this->P_;
    return this->finish_update(y, y_pred, H, P_prior, this->R_);
  }
};

}  // namespace hinf::runtime
