// A star tracker measuring NV reference directions (unit vectors in the orbit frame) in the
// body frame, for the rigid-body attitude state of rigid_body.hpp (docs/maths.md (207)).
// Needs Eigen only.
#pragma once
#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "hinf/models/rigid_body.hpp"

namespace hinf::models {

template <int NV>
class StarTrackerMeasurement {
 public:
  static_assert(NV >= 1, "StarTrackerMeasurement: at least one direction");
  static constexpr int NX = RigidBodyAttitudeProcess::NX, NZ = 3 * NV;
  using State = RigidBodyAttitudeProcess::State;
  using Vector = Eigen::Matrix<double, NZ, 1>;
  using Jacobian = Eigen::Matrix<double, NZ, NX>;

  // Each direction finite and of unit length (to 1e-9); throws std::invalid_argument naming it.
  explicit StarTrackerMeasurement(const std::array<Eigen::Vector3d, NV>& references) : r_(references) {
    for (int i = 0; i < NV; ++i)
      if (!r_[i].allFinite() || std::abs(r_[i].norm() - 1) > 1e-9)
        throw std::invalid_argument("reference_vectors[" + std::to_string(i) + "]: must be a unit vector");
  }

  // h(x) = [A(q) r_1; …; A(q) r_NV].
  Vector h(const State& x) const {
    const Eigen::Matrix3d A = attitude_matrix(x.head<4>());
    Vector z;
    for (int i = 0; i < NV; ++i) z.template segment<3>(3 * i) = A * r_[i];
    return z;
  }

  // H_i = [[(A(q) r_i)×] 0 0], (207).
  Jacobian H(const State& x) const {
    const Eigen::Matrix3d A = attitude_matrix(x.head<4>());
    Jacobian H = Jacobian::Zero();
    for (int i = 0; i < NV; ++i)
      H.template block<3, 3>(3 * i, rigid_body_index::kAttitudeError) = cross_matrix(A * r_[i]);
    return H;
  }

  Vector residual(const Vector& y, const Vector& y_pred) const { return y - y_pred; }

  const std::array<Eigen::Vector3d, NV>& references() const { return r_; }

 private:
  std::array<Eigen::Vector3d, NV> r_;
};

}  // namespace hinf::models
