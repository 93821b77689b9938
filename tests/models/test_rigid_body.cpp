// The rigid-body attitude model and the star tracker (docs/maths.md §31): conservation of the
// torque-free truth, quaternion algebra, and Φ and H against central differences taken on the
// manifold (x ⊞ h e_j, then ⊟).
#include <gtest/gtest.h>

#include <cmath>

#include "hinf/models/rigid_body.hpp"
#include "hinf/models/star_tracker.hpp"

using namespace hinf::models;

namespace {

RigidBodyParameters parameters(double dt) {
  RigidBodyParameters p;
  p.inertia = Eigen::Vector3d(20, 18, 15).asDiagonal();
  p.inertia(0, 1) = p.inertia(1, 0) = 0.7;  // a product of inertia: the cross-coupling terms matter
  p.wheel_momentum = Eigen::Vector3d(0.01, -0.02, 0.005);
  p.sample_time = dt;
  p.substeps = 2;
  return p;
}

RigidBodyAttitudeProcess::State sample_state() {
  RigidBodyAttitudeProcess::State x;
  x.head<4>() = Eigen::Vector4d(0.3, -0.2, 0.5, 0.8).normalized();
  x.segment<3>(4) << 0.01, -0.02, 0.03;
  x.segment<3>(7) << 1e-5, -2e-5, 3e-5;
  return x;
}

}  // namespace

TEST(RigidBody, QuaternionProductComposesAttitudeMatrices) {
  const Quaternion p = Eigen::Vector4d(0.1, 0.7, -0.3, 0.6).normalized();
  const Quaternion q = Eigen::Vector4d(-0.4, 0.2, 0.5, 0.7).normalized();
  EXPECT_LT((attitude_matrix(quaternion_product(p, q)) - attitude_matrix(p) * attitude_matrix(q)).norm(), 1e-14);
  const Eigen::Matrix3d A = attitude_matrix(q);
  EXPECT_LT((A * A.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  // A small rotation about body z by δθ: A(δq ⊗ q) = (I − [δθ×]) A(q) to first order.
  const Eigen::Vector3d dtheta(0, 0, 1e-6);
  const Quaternion dq(0, 0, 0.5e-6, 1);
  EXPECT_LT((attitude_matrix(quaternion_product(dq.normalized(), q)) - (Eigen::Matrix3d::Identity() - cross_matrix(dtheta)) * A)
                .norm(),
            1e-12);
  EXPECT_LT((attitude_error_angles(quaternion_product(dq.normalized(), q), q) - dtheta).norm(), 1e-15);
}

// 002-U1: torque-free, energy and the orbit-frame angular momentum are invariants; RK4 at
// the truth's step (0.1 s) keeps them to 1e-9 relative over 1000 s, and |q| = 1.
TEST(RigidBody, TorqueFreeMotionConservesEnergyAndMomentum) {
  RigidBodyParameters p = parameters(1.0);
  p.wheel_momentum.setZero();
  const RigidBodyDynamics dyn(p);
  Eigen::Matrix<double, 7, 1> s;
  s << 0, 0, 0, 1, 0.01, -0.02, 0.03;
  const double E0 = dyn.kinetic_energy(s.tail<3>());
  const Eigen::Vector3d L0 = dyn.momentum_orbit_frame(s.head<4>(), s.tail<3>());
  const auto zero = [](double) { return Eigen::Vector3d::Zero().eval(); };
  for (int k = 0; k < 10000; ++k) s = dyn.rk4(s, 0.1, zero);
  EXPECT_LT(std::abs(dyn.kinetic_energy(s.tail<3>()) - E0) / E0, 1e-9);
  EXPECT_LT((dyn.momentum_orbit_frame(s.head<4>(), s.tail<3>()) - L0).norm() / L0.norm(), 1e-9);
  EXPECT_LT(std::abs(s.head<4>().norm() - 1), 1e-12);
  // The motion is not trivial: the body rate has turned.
  EXPECT_GT((s.tail<3>() - Eigen::Vector3d(0.01, -0.02, 0.03)).norm(), 1e-3);
}

// 002-U2: Φ = exp(F Δt) of (206) against the central differences of x ↦ f(x ⊞ δx) ⊟ f(x)
// (Δt = 0.01 s, where F's change within the sample is below the tolerance).
TEST(RigidBody, TransitionMatrixMatchesCentralDifferences) {
  const RigidBodyAttitudeProcess model(parameters(0.01));
  const auto x = sample_state();
  const Eigen::Vector3d u(2e-5, 0, -1e-5);
  const auto fx = model.f(x, u);
  const auto Phi = model.F(x, u);
  Eigen::Matrix<double, 9, 9> numeric;
  for (int j = 0; j < 9; ++j) {
    // step sizes of the order of each block's scale
    const double h = j < 3 ? 1e-6 : j < 6 ? 1e-7 : 1e-7;
    RigidBodyAttitudeProcess::Error e = RigidBodyAttitudeProcess::Error::Zero();
    e(j) = h;
    const auto plus = RigidBodyAttitudeProcess::difference(model.f(model.boxplus(x, e), u), fx);
    const auto minus = RigidBodyAttitudeProcess::difference(model.f(model.boxplus(x, -e), u), fx);
    numeric.col(j) = (plus - minus) / (2 * h);
  }
  EXPECT_LT((Phi - numeric).norm(), 1e-6 * Phi.norm()) << "Phi\n" << Phi << "\nnumeric\n" << numeric;
  // and the continuous-time blocks are the ones of (205)
  const auto F = model.F_continuous(x);
  EXPECT_LT((F.block<3, 3>(3, 6) - model.dynamics().J_inv).norm(), 1e-15);
}

TEST(RigidBody, StarTrackerJacobianMatchesCentralDifferences) {
  const RigidBodyAttitudeProcess model(parameters(1.0));
  const StarTrackerMeasurement<2> st({Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0.6, 0.8)});
  const auto x = sample_state();
  const auto H = st.H(x);
  Eigen::Matrix<double, 6, 9> numeric;
  for (int j = 0; j < 9; ++j) {
    RigidBodyAttitudeProcess::Error e = RigidBodyAttitudeProcess::Error::Zero();
    e(j) = 1e-6;
    numeric.col(j) = (st.h(model.boxplus(x, e)) - st.h(model.boxplus(x, -e))) / 2e-6;
  }
  EXPECT_LT((H - numeric).norm(), 1e-6 * H.norm());
  EXPECT_THROW(StarTrackerMeasurement<1>({Eigen::Vector3d(1, 1, 0)}), std::invalid_argument);
}

TEST(RigidBody, ParametersAreValidated) {
  RigidBodyParameters p = parameters(1.0);
  p.inertia(2, 2) = -1;
  EXPECT_THROW(RigidBodyAttitudeProcess{p}, std::invalid_argument);
  p = parameters(1.0);
  p.substeps = 0;
  EXPECT_THROW(RigidBodyAttitudeProcess{p}, std::invalid_argument);
  p = parameters(0.0);
  EXPECT_THROW(RigidBodyAttitudeProcess{p}, std::invalid_argument);
}
