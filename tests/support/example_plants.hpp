// Small plants with known answers shared by the observer-form tests (docs/maths.md §18): a
// certain plant from its matrices, the scalar plant of (127), the double integrator, the
// triple integrator with a known input.
#pragma once
#include <Eigen/Dense>
#include <utility>

#include "hinf/models/plant.hpp"

namespace hinf::test {

// x(k+1) = A x + B w, y = C x + D v, z = L x: no uncertainty, no known input.
inline Plant certain_plant(Eigen::MatrixXd A, Eigen::MatrixXd B, Eigen::MatrixXd C, Eigen::MatrixXd D,
                           Eigen::MatrixXd L) {
  Plant P;
  P.A = std::move(A);
  P.B = std::move(B);
  P.C = std::move(C);
  P.D = std::move(D);
  P.L = std::move(L);
  P.H = Eigen::MatrixXd(P.A.rows(), 0);
  P.E = Eigen::MatrixXd(0, P.A.rows());
  P.G = Eigen::MatrixXd(P.A.rows(), 0);
  return P;
}

// The scalar plant of docs/maths.md (127).
inline Plant scalar_plant(double a, double b, double c, double d, double l) {
  const auto s = [](double v) { return Eigen::MatrixXd::Constant(1, 1, v); };
  return certain_plant(s(a), s(b), s(c), s(d), s(l));
}

// Position and velocity driven by a random acceleration held over T, position measured with
// noise sigma, both states estimated (L = I).
inline Plant double_integrator(double T, double sigma) {
  Eigen::MatrixXd A(2, 2), B(2, 1), C(1, 2);
  A << 1, T, 0, 1;
  B << T * T / 2, T;
  C << 1, 0;
  return certain_plant(A, B, C, Eigen::MatrixXd::Constant(1, 1, sigma), Eigen::MatrixXd::Identity(2, 2));
}

// Position, velocity, acceleration (T = 0.05 s), position measured; a commanded acceleration
// (the known input u, docs/maths.md (120)) enters velocity and position.
inline Plant triple_integrator_with_input() {
  const double T = 0.05;
  Eigen::MatrixXd A(3, 3), B(3, 1), C(1, 3), G(3, 1);
  A << 1, T, T * T / 2, 0, 1, T, 0, 0, 1;
  B << T * T * T / 6, T * T / 2, T;
  G << T * T / 2, T, 0;
  C << 1, 0, 0;
  Plant P = certain_plant(A, B, C, Eigen::MatrixXd::Constant(1, 1, 0.2), Eigen::MatrixXd::Identity(3, 3));
  P.G = G;
  return P;
}

}  // namespace hinf::test
