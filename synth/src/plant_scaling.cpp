// docs/maths.md §4.4; see plant_scaling.hpp.
#include "hinf/synth/plant_scaling.hpp"

#include <cmath>
#include <sstream>

#include "hinf/certify/balance.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {
// Rounds of (state balancing, measurement rows, input/output units): the later rounds
// settle the interplay (C's rows enter the state balance and the other way round).
constexpr int kRounds = 3;

// The uncertainty split (docs/maths.md (24)): the power of two s with ‖sH‖ ≈ ‖E/s‖.
double split_for(const Plant& p) {
  if (!p.uncertain() || !(p.H.norm() > 0) || !(p.E.norm() > 0)) return 1.0;
  return unit_for(std::sqrt(p.H.norm() / p.E.norm()));
}

std::string exponents(const VectorXd& v) {
  std::ostringstream o;
  o << "[";
  for (int i = 0; i < v.size(); ++i) o << (i ? ", " : "") << std::ilogb(v(i));
  o << "]";
  return o.str();
}

MatrixXd stack_rows(const MatrixXd& a, const MatrixXd& b, const MatrixXd& c, const MatrixXd& d) {
  MatrixXd out(a.rows() + b.rows() + c.rows() + d.rows(), a.cols());
  out << a, b, c, d;
  return out;
}
}  // namespace

std::string PlantScaling::summary() const {
  std::ostringstream o;
  o << "x: 2^" << exponents(state) << ", y: 2^" << exponents(measurement) << ", w,v: 2^" << std::ilogb(input)
    << ", z: 2^" << std::ilogb(output) << ", H/E: 2^" << std::ilogb(uncertainty);
  return o.str();
}

double unit_for(double v) {
  if (!(v > 0) || !std::isfinite(v)) return 1.0;
  return std::ldexp(1.0, -static_cast<int>(std::lround(std::log2(v))));
}

PlantScaling identity_scaling(const Plant& plant) {
  PlantScaling s;
  s.state = VectorXd::Ones(plant.n());
  s.measurement = VectorXd::Ones(plant.m());
  return s;
}

PlantScaling choose_scaling(const Plant& plant) {
  PlantScaling s = identity_scaling(plant);
  for (int round = 0; round < kRounds; ++round) {
    const Plant p = scaled_plant(plant, s);
    // states: TB01ID on [Ã, B̃, H̃; C̃; L̃; Ẽ] (docs/maths.md (108))
    MatrixXd In(p.n(), p.p() + p.j());
    In << p.B, p.H;
    const VectorXd d = certify::balancing_scaling(p.A, In, stack_rows(p.C, p.L, p.E, MatrixXd(0, p.n())));
    s.state = s.state.cwiseProduct(d);
    // measurements: unit rows of [C̃ D̃]; then inputs ‖[B̃; D̃]‖ ≈ 1 and output ‖L̃‖ ≈ 1 (eq. (109))
    const Plant q = scaled_plant(plant, s);
    for (int i = 0; i < q.m(); ++i)
      s.measurement(i) *= unit_for(std::hypot(q.C.row(i).norm(), q.D.row(i).norm()));
    const Plant r = scaled_plant(plant, s);
    s.input *= unit_for(std::hypot(r.B.norm(), r.D.norm()));
    s.output *= unit_for(r.L.norm());
    s.uncertainty *= split_for(r);
  }
  return s;
}

PlantScaling uncertainty_split(const Plant& plant) {
  PlantScaling s = identity_scaling(plant);
  s.uncertainty = split_for(plant);
  return s;
}

Plant scaled_plant(const Plant& P, const PlantScaling& s) {
  const auto Dinv = s.state.cwiseInverse().asDiagonal();
  const auto D = s.state.asDiagonal();
  const auto T = s.measurement.asDiagonal();
  Plant q;
  q.A = Dinv * P.A * D;
  q.B = Dinv * P.B * s.input;
  q.C = T * P.C * D;
  q.D = T * P.D * s.input;
  q.L = s.output * P.L * D;
  q.H = Dinv * P.H * s.uncertainty;
  q.E = P.E * D / s.uncertainty;
  q.G = P.G.size() > 0 ? MatrixXd(Dinv * P.G) : MatrixXd::Zero(P.n(), 0);  // u keeps its units
  q.F_blocks = P.F_blocks;
  return q;
}

// ỹ = T y, ẑ̃ = σ_z ẑ, x_F = D x̃_F (eq. (111)); an observer's K maps as B_F, G_F as G.
Filter scaled_filter(const Filter& F, const PlantScaling& s) {
  const auto Dinv = s.state.cwiseInverse().asDiagonal();
  const auto D = s.state.asDiagonal();
  const auto Tinv = s.measurement.cwiseInverse().asDiagonal();
  Filter f = F;
  f.A_F = Dinv * F.A_F * D;
  f.B_F = Dinv * F.B_F * Tinv;
  f.C_F = s.output * F.C_F * D;
  if (F.K.size() > 0) f.K = Dinv * F.K * Tinv;
  if (F.G_F.size() > 0) f.G_F = Dinv * F.G_F;
  if (F.M.size() > 0) f.M = Dinv * F.M * Tinv;  // the filtered observer (140): M as K, D_F as C_F·B_F
  if (F.D_F.size() > 0) f.D_F = s.output * F.D_F * Tinv;
  return f;
}

Filter user_filter(const Filter& F, const PlantScaling& s) {
  const auto Dinv = s.state.cwiseInverse().asDiagonal();
  const auto D = s.state.asDiagonal();
  const auto T = s.measurement.asDiagonal();
  Filter f = F;
  f.A_F = D * F.A_F * Dinv;
  f.B_F = D * F.B_F * T;
  f.C_F = F.C_F * Dinv / s.output;
  if (F.K.size() > 0) f.K = D * F.K * T;
  if (F.G_F.size() > 0) f.G_F = D * F.G_F;
  if (F.M.size() > 0) f.M = D * F.M * T;
  if (F.D_F.size() > 0) f.D_F = F.D_F * T / s.output;
  return f;
}

}  // namespace hinf::synth
