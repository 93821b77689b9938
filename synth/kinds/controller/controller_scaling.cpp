// Equilibration of a generalised plant (controller_scaling.hpp).
#include "controller_scaling.hpp"

#include <cmath>

#include "hinf/certify/balance.hpp"
#include "hinf/synth/plant_scaling.hpp"

namespace hinf::synth {

namespace {

Eigen::MatrixXd hcat(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  Eigen::MatrixXd m(a.rows(), a.cols() + b.cols());
  m << a, b;
  return m;
}
Eigen::MatrixXd vcat(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  Eigen::MatrixXd m(a.rows() + b.rows(), a.cols());
  m << a, b;
  return m;
}

}  // namespace

ControllerScaling choose_controller_scaling(const hinf::GeneralisedPlant& P) {
  ControllerScaling s;
  s.state = certify::balancing_scaling(P.A, hcat(P.B1, P.B2), vcat(P.C1, P.C2));
  s.u = Eigen::VectorXd::Ones(P.nu());
  s.y = Eigen::VectorXd::Ones(P.ny());
  hinf::GeneralisedPlant B = scaled_generalised_plant(P, s);  // states balanced
  // time: the balanced A's largest entry to ~1 (its frequencies to ~1 rad per unit time)
  if (P.time == hinf::TimeDomain::Continuous) s.time = 1.0 / unit_for(B.A.cwiseAbs().maxCoeff());
  B = scaled_generalised_plant(P, s);
  for (int j = 0; j < P.nu(); ++j) s.u(j) = unit_for(vcat(B.B2.col(j), B.D12.col(j)).norm());
  for (int i = 0; i < P.ny(); ++i) s.y(i) = 1.0 / unit_for(hcat(B.C2.row(i), B.D21.row(i)).norm());
  B = scaled_generalised_plant(P, s);
  s.w = unit_for(vcat(vcat(B.B1, B.D11), B.D21).colwise().norm().maxCoeff());
  s.z = 1.0 / unit_for(hcat(hcat(B.C1, B.D11), B.D12).rowwise().norm().maxCoeff());
  return s;
}

hinf::GeneralisedPlant scaled_generalised_plant(const hinf::GeneralisedPlant& P, const ControllerScaling& s) {
  const Eigen::VectorXd d = s.state, d_inv = s.state.cwiseInverse(), y_inv = s.y.cwiseInverse();
  hinf::GeneralisedPlant Q = P;
  Q.A = d_inv.asDiagonal() * P.A * d.asDiagonal() / s.time;
  Q.B1 = d_inv.asDiagonal() * P.B1 * (s.w / s.time);
  Q.B2 = d_inv.asDiagonal() * P.B2 * s.u.asDiagonal() / s.time;
  Q.C1 = P.C1 * d.asDiagonal() / s.z;
  Q.D11 = P.D11 * (s.w / s.z);
  Q.D12 = P.D12 * s.u.asDiagonal() / s.z;
  Q.C2 = y_inv.asDiagonal() * P.C2 * d.asDiagonal();
  Q.D21 = y_inv.asDiagonal() * P.D21 * s.w;
  return Q;
}

hinf::Controller unscaled_controller(const hinf::Controller& K, const ControllerScaling& s) {
  const Eigen::VectorXd y_inv = s.y.cwiseInverse();
  hinf::Controller out;
  out.A_K = s.time * K.A_K;
  out.B_K = s.time * K.B_K * y_inv.asDiagonal();
  out.C_K = s.u.asDiagonal() * K.C_K;
  out.D_K = s.u.asDiagonal() * K.D_K * y_inv.asDiagonal();
  return out;
}

}  // namespace hinf::synth
