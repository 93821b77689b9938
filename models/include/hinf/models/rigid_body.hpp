// A rigid body's attitude, rate and disturbance torque, the process model of the gyroless
// augmented EKF (docs/maths.md §31):
//
//   x = [q (scalar-last unit quaternion, orbit frame O to body B); ω (rad/s, in B);
//        T_d (disturbance torque, N m, in B)]                      NS = 10
//   δx = [δθ (body-frame attitude error, rad); δω; δT]             NX = 9
//   u = T_c, the known control torque (N m, in B)
//
// The model types follow runtime/ekf.hpp's requirements with NS beside NX and the manifold
// hook boxplus (the MEKF correction (208)). Needs Eigen only.
#pragma once
#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <stdexcept>

#include "hinf/models/attitude.hpp"

namespace hinf::models {

// Offsets of the blocks of x and of δx.
namespace rigid_body_index {
constexpr int kQuaternion = 0, kRate = 4, kTorque = 7;       // in x
constexpr int kAttitudeError = 0, kRateError = 3, kTorqueError = 6;  // in δx
}  // namespace rigid_body_index

// q = [q_v; q₄] of Shuster's convention (docs/maths.md (201)–(202)).
using Quaternion = Eigen::Vector4d;

// A(q): orbit-frame components to body components, (201).
inline Eigen::Matrix3d attitude_matrix(const Quaternion& q) {
  const Eigen::Vector3d qv = q.head<3>();
  const double q4 = q(3);
  return (q4 * q4 - qv.squaredNorm()) * Eigen::Matrix3d::Identity() + 2 * qv * qv.transpose() - 2 * q4 * cross_matrix(qv);
}

// p ⊗ q, (202): A(p ⊗ q) = A(p) A(q).
inline Quaternion quaternion_product(const Quaternion& p, const Quaternion& q) {
  const Eigen::Vector3d pv = p.head<3>(), qv = q.head<3>();
  Quaternion r;
  r.head<3>() = p(3) * qv + q(3) * pv - pv.cross(qv);
  r(3) = p(3) * q(3) - pv.dot(qv);
  return r;
}

inline Quaternion quaternion_inverse(const Quaternion& q) {
  return Quaternion(-q(0), -q(1), -q(2), q(3));
}

// The rotation vector of q_a ⊗ q_b⁻¹ to first order, 2 δq_v with δq₄ ≥ 0 (docs/maths.md (212)).
inline Eigen::Vector3d attitude_error_angles(const Quaternion& q_a, const Quaternion& q_b) {
  Quaternion dq = quaternion_product(q_a, quaternion_inverse(q_b));
  if (dq(3) < 0) dq = -dq;
  return 2 * dq.head<3>();
}

// q̇ = ½ Ω(ω) q, (203).
inline Quaternion quaternion_rate(const Quaternion& q, const Eigen::Vector3d& w) {
  Quaternion r;
  r.head<3>() = 0.5 * (-w.cross(q.head<3>()) + q(3) * w);
  r(3) = -0.5 * w.dot(q.head<3>());
  return r;
}

struct RigidBodyParameters {
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();  // J, kg m² (symmetric PD)
  Eigen::Vector3d wheel_momentum = Eigen::Vector3d::Zero();  // h, N m s (constant)
  double sample_time = 1;  // Δt, s
  int substeps = 1;        // RK4 steps per sample in f

  // Throws std::invalid_argument naming the field.
  void validate() const {
    if (!inertia.allFinite() || (inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-12 * inertia.norm() ||
        Eigen::LLT<Eigen::Matrix3d>(inertia).info() != Eigen::Success)
      throw std::invalid_argument("inertia: must be symmetric positive definite");
    if (!wheel_momentum.allFinite()) throw std::invalid_argument("wheel_momentum: must be finite");
    if (!(sample_time > 0) || !std::isfinite(sample_time)) throw std::invalid_argument("sample_time: must be > 0");
    if (substeps < 1) throw std::invalid_argument("substeps: must be >= 1");
  }
};

// The rigid body of (203)–(204): ẋ of [q; ω] for the torque T = T_c + T_d.
struct RigidBodyDynamics {
  Eigen::Matrix3d J, J_inv;
  Eigen::Vector3d h;

  explicit RigidBodyDynamics(const RigidBodyParameters& p)
      : J(p.inertia), J_inv(p.inertia.inverse()), h(p.wheel_momentum) {}

  Eigen::Matrix<double, 7, 1> derivative(const Eigen::Matrix<double, 7, 1>& s, const Eigen::Vector3d& torque) const {
    const Eigen::Vector3d w = s.tail<3>();
    Eigen::Matrix<double, 7, 1> d;
    d.head<4>() = quaternion_rate(s.head<4>(), w);
    d.tail<3>() = J_inv * (torque - w.cross(J * w + h));
    return d;
  }

  // One RK4 step of length dt with the torque of torque_at(τ) (τ ∈ [0, dt]); q renormalised.
  template <class TorqueAt>
  Eigen::Matrix<double, 7, 1> rk4(const Eigen::Matrix<double, 7, 1>& s, double dt, TorqueAt&& torque_at) const {
    const Eigen::Vector3d T0 = torque_at(0.0), Th = torque_at(0.5 * dt), T1 = torque_at(dt);
    const Eigen::Matrix<double, 7, 1> k1 = derivative(s, T0);
    const Eigen::Matrix<double, 7, 1> k2 = derivative(s + 0.5 * dt * k1, Th);
    const Eigen::Matrix<double, 7, 1> k3 = derivative(s + 0.5 * dt * k2, Th);
    const Eigen::Matrix<double, 7, 1> k4 = derivative(s + dt * k3, T1);
    Eigen::Matrix<double, 7, 1> n = s + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    n.head<4>().normalize();
    return n;
  }

  double kinetic_energy(const Eigen::Vector3d& w) const { return 0.5 * w.dot(J * w); }
  // The angular momentum in the orbit frame (conserved without torque): A(q)ᵀ (J ω + h).
  Eigen::Vector3d momentum_orbit_frame(const Quaternion& q, const Eigen::Vector3d& w) const {
    return attitude_matrix(q).transpose() * (J * w + h);
  }
};

// The augmented process model of the AEKF (docs/maths.md §31.1–§31.2).
class RigidBodyAttitudeProcess {
 public:
  static constexpr int NS = 10, NX = 9, NU = 3;
  using State = Eigen::Matrix<double, NS, 1>;
  using Error = Eigen::Matrix<double, NX, 1>;
  using Input = Eigen::Vector3d;
  using Jacobian = Eigen::Matrix<double, NX, NX>;

  explicit RigidBodyAttitudeProcess(const RigidBodyParameters& p) : p_((p.validate(), p)), dyn_(p) {}

  // x(k+1): RK4 over Δt in `substeps` steps with T_c + T̂_d held (203)–(204).
  State f(const State& x, const Input& u) const {
    const Eigen::Vector3d torque = u + x.segment<3>(rigid_body_index::kTorque);
    Eigen::Matrix<double, 7, 1> s = x.head<7>();
    const double dt = p_.sample_time / p_.substeps;
    for (int i = 0; i < p_.substeps; ++i) s = dyn_.rk4(s, dt, [&](double) { return torque; });
    State next = x;
    next.head<7>() = s;
    return next;
  }

  // The continuous-time error dynamics F of (205) at x.
  Jacobian F_continuous(const State& x) const {
    using namespace rigid_body_index;
    const Eigen::Vector3d w = x.segment<3>(kRate);
    Jacobian F = Jacobian::Zero();
    F.block<3, 3>(kAttitudeError, kAttitudeError) = -cross_matrix(w);
    F.block<3, 3>(kAttitudeError, kRateError).setIdentity();
    F.block<3, 3>(kRateError, kRateError) = dyn_.J_inv * (cross_matrix(dyn_.J * w + dyn_.h) - cross_matrix(w) * dyn_.J);
    F.block<3, 3>(kRateError, kTorqueError) = dyn_.J_inv;
    return F;
  }

  // Φ = exp(F Δt), (206).
  Jacobian F(const State& x, const Input&) const {
    const Jacobian A = F_continuous(x) * p_.sample_time;
    return A.exp();
  }

  // Q_d = Δt Γ Q_T Γᵀ for Q_T = q_torque I (206).
  Jacobian discrete_process_noise(double q_torque) const {
    Jacobian Q = Jacobian::Zero();
    Q.block<3, 3>(rigid_body_index::kTorqueError, rigid_body_index::kTorqueError) =
        Eigen::Matrix3d::Identity() * (p_.sample_time * q_torque);
    return Q;
  }

  // x ⊞ δx, the MEKF correction (208).
  State boxplus(const State& x, const Error& dx) const {
    using namespace rigid_body_index;
    Quaternion dq;
    dq.head<3>() = 0.5 * dx.segment<3>(kAttitudeError);
    dq(3) = 1;
    State y = x;
    y.head<4>() = quaternion_product(dq, x.head<4>()).normalized();
    y.segment<3>(kRate) += dx.segment<3>(kRateError);
    y.segment<3>(kTorque) += dx.segment<3>(kTorqueError);
    return y;
  }

  // x_a ⊟ x_b in error coordinates, (212): [2 δq_v; ω_a − ω_b; T_a − T_b].
  static Error difference(const State& a, const State& b) {
    using namespace rigid_body_index;
    Error e;
    e.segment<3>(kAttitudeError) = attitude_error_angles(a.head<4>(), b.head<4>());
    e.segment<3>(kRateError) = a.segment<3>(kRate) - b.segment<3>(kRate);
    e.segment<3>(kTorqueError) = a.segment<3>(kTorque) - b.segment<3>(kTorque);
    return e;
  }

  const RigidBodyParameters& parameters() const { return p_; }
  const RigidBodyDynamics& dynamics() const { return dyn_; }

 private:
  RigidBodyParameters p_;
  RigidBodyDynamics dyn_;
};

}  // namespace hinf::models
