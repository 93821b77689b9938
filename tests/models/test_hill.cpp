// HillModel (docs/maths.md §9) against the scalar Hill/CW equations written out here, the
// closed-form Clohessy-Wiltshire transition matrix, and RK4 integration.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "cw_closed_form.hpp"
#include "hinf/models/hill.hpp"

using hinf::models::Discretisation;
using hinf::models::HillModel;
using HillState = HillModel::State;
using Input = HillModel::Input;
using hinf::test::cw_closed_form;

namespace {

// The equations docs/maths.md (62) as scalars: xdd = 3w^2 x + 2w yd + Fx/m, ydd = -2w xd + Fy/m,
// zdd = -w^2 z + Fz/m, with thrust F = u_ext + K s.
HillState rhs(const HillState& s, const Input& u_ext, double w, double m, const HillModel::Gain& K) {
  const Input F = u_ext + K * s;
  HillState d;
  d(0) = s(3);
  d(1) = s(4);
  d(2) = s(5);
  d(3) = 3 * w * w * s(0) + 2 * w * s(4) + F(0) / m;
  d(4) = -2 * w * s(3) + F(1) / m;
  d(5) = -w * w * s(2) + F(2) / m;
  return d;
}

HillState rk4(HillState s, const Input& u, double w, double m, const HillModel::Gain& K, double T, int steps) {
  const double h = T / steps;
  for (int i = 0; i < steps; ++i) {
    const HillState k1 = rhs(s, u, w, m, K);
    const HillState k2 = rhs(s + 0.5 * h * k1, u, w, m, K);
    const HillState k3 = rhs(s + 0.5 * h * k2, u, w, m, K);
    const HillState k4 = rhs(s + h * k3, u, w, m, K);
    s += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return s;
}

HillModel::Gain paper_K() {
  HillModel::Gain K;
  K << -2.2541, -0.0071, -0.0072, -22.3975, 2.3256, 1.9369,  //
      -0.0104, -2.2493, -0.0055, 2.3259, -23.7456, 1.4544,   //
      -0.0072, -0.0055, -2.2471, 1.9357, 1.4552, -24.2818;
  return K;
}

double rel_err(const HillState& a, const HillState& b) { return (a - b).norm() / std::max(1.0, b.norm()); }

}  // namespace

TEST(HillModel, ContinuousDynamicsMatchScalarEquations) {
  const double w = 1.1e-3, m = 500.0;
  const HillModel::Gain K = paper_K();
  const HillModel open(w, m, 1.0), closed(w, m, 1.0, K);
  const HillState s = (HillState() << 600, 550, 1040, 0.02, -0.08, 0.03).finished();
  const Input u(0.3, -0.2, 0.1);
  EXPECT_LE((open.xdot(s, u) - rhs(s, u, w, m, HillModel::Gain::Zero())).norm(), 1e-15 * rhs(s, u, w, m, HillModel::Gain::Zero()).norm() + 1e-18);
  EXPECT_LE((closed.xdot(s, u) - rhs(s, u, w, m, K)).norm(), 1e-14 * rhs(s, u, w, m, K).norm());
}

TEST(HillModel, EulerIsOneExplicitEulerStep) {
  const double w = 7.2722e-5, m = 1000.0, T = 0.1;
  const HillModel::Gain K = paper_K();
  const HillModel model(w, m, T, K, Discretisation::Euler);
  const HillState s = (HillState() << 600, 550, 1040, 0.02, -0.08, 0.03).finished();
  const Input u(1.0, -2.0, 0.5);
  const HillState expect = s + T * rhs(s, u, w, m, K);
  EXPECT_LE(rel_err(model.f(s, u), expect), 1e-15);
  EXPECT_EQ(model.F(s, u), model.A());
  // Jacobian of f (linear): columns by central differences.
  for (int j = 0; j < 6; ++j) {
    HillState e = HillState::Zero();
    e(j) = 1.0;
    const HillState col = (model.f(s + e, u) - model.f(s - e, u)) / 2.0;
    EXPECT_LE((col - model.A().col(j)).norm(), 1e-9) << "column " << j;
  }
}

TEST(HillModel, ZohWithoutThrustEqualsClohessyWiltshireClosedForm) {
  // A long sample time (a sixth of an orbit) so the test sees the orbital dynamics.
  const double n = 1.1e-3, T = 2 * M_PI / n / 6;
  const HillModel model(n, 1000.0, T, Discretisation::ZeroOrderHold);
  const std::array<HillState, 3> states = {(HillState() << 600, 550, 1040, 0.02, -0.08, 0.03).finished(),
                                       (HillState() << -10, 0, 5, 0, 0.5, -0.1).finished(),
                                       (HillState() << 0, 100, 0, 0.3, 0, 0).finished()};
  for (const HillState& s0 : states) EXPECT_LE(rel_err(model.f(s0, Input::Zero()), cw_closed_form(s0, n, T)), 1e-12);
  // Paper's parameters too (tiny wT).
  const HillModel paper(7.2722e-5, 1000.0, 0.1, Discretisation::ZeroOrderHold);
  for (const HillState& s0 : states)
    EXPECT_LE(rel_err(paper.f(s0, Input::Zero()), cw_closed_form(s0, 7.2722e-5, 0.1)), 1e-13);
}

TEST(HillModel, ZohThrustAndControlMatchRk4) {
  const double w = 1.1e-3, m = 500.0, T = 20.0;
  const HillState s0 = (HillState() << 600, 550, 1040, 0.02, -0.08, 0.03).finished();
  const Input u(0.4, -0.3, 0.2);
  const HillModel open(w, m, T, Discretisation::ZeroOrderHold);
  EXPECT_LE(rel_err(open.f(s0, u), rk4(s0, u, w, m, HillModel::Gain::Zero(), T, 2000)), 1e-11);
  // Closed loop u = K x (a milder gain than the paper's so RK4 with 2000 steps is accurate).
  const HillModel::Gain K = 0.01 * paper_K();
  const HillModel closed(w, m, T, K, Discretisation::ZeroOrderHold);
  EXPECT_LE(rel_err(closed.f(s0, u), rk4(s0, u, w, m, K, T, 2000)), 1e-11);
}

TEST(HillModel, EulerAndZohAgreeToFirstOrder) {
  // |A_euler - A_zoh| = O(T^2): halving T divides the difference by ~4.
  const double w = 1.1e-3, m = 500.0;
  const HillModel::Gain K = 0.01 * paper_K();
  auto diff = [&](double T) {
    return (HillModel(w, m, T, K, Discretisation::Euler).A() - HillModel(w, m, T, K, Discretisation::ZeroOrderHold).A()).norm();
  };
  const double r = diff(1.0) / diff(0.5);
  EXPECT_NEAR(r, 4.0, 0.1);
}

TEST(HillModel, InvalidParametersThrow) {
  EXPECT_THROW(HillModel(-1e-3, 1000, 0.1), std::invalid_argument);
  EXPECT_THROW(HillModel(1e-3, 0.0, 0.1), std::invalid_argument);
  EXPECT_THROW(HillModel(1e-3, 1000, 0.0), std::invalid_argument);
  EXPECT_THROW(HillModel(std::numeric_limits<double>::quiet_NaN(), 1000, 0.1), std::invalid_argument);
  HillModel::Gain K = HillModel::Gain::Zero();
  K(1, 2) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(HillModel(1e-3, 1000, 0.1, K), std::invalid_argument);
}
