// Generic linear discrete-time model and measurement, fixed size (or Eigen::Dynamic, sized
// by the matrices given: the Python module's EKF):
//     x(k+1) = F x(k) + G u(k),     y(k) = H x(k)
// They satisfy the process/measurement interfaces used by Ekf and Rekf (see ekf.hpp).
#pragma once

#include <Eigen/Dense>

namespace hinf::models {

// A fixed dimension must be positive; Eigen::Dynamic sizes by the matrices given.
constexpr bool valid_dimension(int n) { return n > 0 || n == Eigen::Dynamic; }

template <int NX_, int NU_>
class LinearModel {
  static_assert(valid_dimension(NX_) && valid_dimension(NU_), "LinearModel: dimensions must be positive (or Dynamic)");

 public:
  static constexpr int NX = NX_;
  static constexpr int NU = NU_;
  using State = Eigen::Matrix<double, NX, 1>;
  using Input = Eigen::Matrix<double, NU, 1>;
  using StateMatrix = Eigen::Matrix<double, NX, NX>;
  using InputMatrix = Eigen::Matrix<double, NX, NU>;

  LinearModel(const StateMatrix& F, const InputMatrix& G) : F_(F), G_(G) {}

  State f(const State& x, const Input& u) const { return F_ * x + G_ * u; }
  const StateMatrix& F(const State& /*x*/, const Input& /*u*/) const { return F_; }
  const InputMatrix& G() const { return G_; }

 private:
  StateMatrix F_;
  InputMatrix G_;
};

template <int NX_, int NZ_>
class LinearMeasurement {
  static_assert(valid_dimension(NX_) && valid_dimension(NZ_), "LinearMeasurement: dimensions must be positive");

 public:
  static constexpr int NX = NX_;
  static constexpr int NZ = NZ_;
  using State = Eigen::Matrix<double, NX, 1>;
  using Vector = Eigen::Matrix<double, NZ, 1>;
  using Jacobian = Eigen::Matrix<double, NZ, NX>;

  explicit LinearMeasurement(const Jacobian& H) : H_(H) {}

  Vector h(const State& x) const { return H_ * x; }
  const Jacobian& H(const State& /*x*/) const { return H_; }
  Vector residual(const Vector& y, const Vector& y_pred) const { return y - y_pred; }

 private:
  Jacobian H_;
};

}  // namespace hinf::models
