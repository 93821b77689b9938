// Relative position measured directly (docs/maths.md §10 and §9.8, C = [I3 0_3]):  y = C x, x = [r; v].
#pragma once

#include <Eigen/Dense>

namespace hinf::models {

class CartesianPosition {
 public:
  static constexpr int NX = 6;
  static constexpr int NZ = 3;
  using State = Eigen::Matrix<double, 6, 1>;
  using Vector = Eigen::Matrix<double, 3, 1>;
  using Jacobian = Eigen::Matrix<double, 3, 6>;

  CartesianPosition() { C_ << Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Zero(); }

  Vector h(const State& x) const { return x.head<3>(); }
  const Jacobian& H(const State& /*x*/) const { return C_; }
  const Jacobian& C() const { return C_; }
  Vector residual(const Vector& y, const Vector& y_pred) const { return y - y_pred; }

 private:
  Jacobian C_;
};

}  // namespace hinf::models
