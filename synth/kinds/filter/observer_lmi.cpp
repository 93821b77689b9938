#include "observer_lmi.hpp"

#include "hinf/common/error.hpp"
#include "theorem1.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;
using hinf::Plant;

namespace {
ObserverLmi build(const Plant& P, const double* g_fixed, Estimate estimate) {
  const int n = P.n(), p = P.p(), q = P.q(), l = P.l(), m = P.m();
  const bool unc = P.uncertain();
  std::vector<int> blocks{n, n, p, q, l};
  if (unc) blocks.push_back(P.j());
  ObserverLmi O;
  O.lmi = lmi::LmiProblem(blocks);
  auto& M = O.lmi;  // M(x), docs/maths.md (124)
  O.P = M.add_symmetric("P", n);
  O.Y = M.add_full("Y", n, m);
  if (estimate == Estimate::Filtered) O.N = M.add_full("N", l, m);
  if (unc) O.lambda = declare_multipliers(M, P);
  if (!g_fixed) O.g = M.add_scalar("gamma_squared");
  else O.margin = M.add_scalar("margin");

  const MatrixXd In = MatrixXd::Identity(n, n);
  // row 1:  [ −P  PA − YC  PB  −YD  0  PH ]
  M.add_term(0, 0, O.P, -In, In);
  M.add_term(0, 1, O.P, In, P.A);
  M.add_term(0, 1, O.Y, -In, P.C);
  M.add_term(0, 2, O.P, In, P.B);
  M.add_term(0, 3, O.Y, -In, P.D);
  if (unc) M.add_term(0, 5, O.P, In, P.H);
  // row 2:  [ ∗  −P + λEᵀE  0  0  Lᵀ  0 ]
  M.add_term(1, 1, O.P, -In, In);
  if (unc) add_multiplier_EtE(M, P, O.lambda, P.E, 1);
  M.add_constant(1, 4, P.L.transpose());
  if (O.N) {  // filtered (142): output row (L − N C, 0, −N D)
    M.add_term(1, 4, *O.N, -P.C.transpose(), MatrixXd::Identity(l, l), /*transpose=*/true);
    M.add_term(3, 4, *O.N, -P.D.transpose(), MatrixXd::Identity(l, l), /*transpose=*/true);
  }
  // rows 3–6: −gI, −gI, −I, −λI
  add_filter_lmi_tail(M, P, g_fixed, O.g, O.margin, O.lambda, 2);
  return O;
}
}  // namespace

ObserverLmi build_observer_lmi(const Plant& P, Estimate estimate) { return build(P, nullptr, estimate); }

ObserverLmi build_observer_lmi_backoff(const Plant& P, double g_fixed, Estimate estimate) {
  return build(P, &g_fixed, estimate);
}

std::vector<lmi::SparseEntry> observer_basis_error(const ObserverLmi& O, const Plant& plant) {
  if (!plant.uncertain()) return {};
  return rounded_EtE_basis_error(O.lmi, O.lambda, 1, plant);
}

certify::ObserverPoint observer_point(const ObserverLmi& O, const Plant& /*plant*/, const Eigen::VectorXd& x, double g) {
  certify::ObserverPoint pt;
  pt.P = O.lmi.value(O.P, x);
  pt.Y = O.lmi.value(O.Y, x);
  if (O.N) pt.N = O.lmi.value(*O.N, x);
  pt.lambda = multiplier_values(O.lmi, O.lambda, x);
  pt.g = g;
  return pt;
}

hinf::Filter recover_observer(const certify::ObserverPoint& pt, const Plant& plant) {
  const Eigen::LLT<MatrixXd> P(pt.P);
  if (P.info() != Eigen::Success)
    throw Error(ErrorCode::NumericalFailure, "recovery: P is not positive definite at the solution");
  hinf::Filter f;
  f.form = FilterForm::Observer;
  f.K = P.solve(pt.Y);
  f.A_F = plant.A - f.K * plant.C;
  f.B_F = f.K;
  f.C_F = plant.L;
  f.G_F = plant.G.size() > 0 ? plant.G : MatrixXd::Zero(plant.n(), 0);
  if (pt.N.size() > 0) {  // (144)
    f.M = Eigen::CompleteOrthogonalDecomposition<MatrixXd>(plant.L).solve(pt.N);
    f.D_F = plant.L * f.M;
    f.C_F = plant.L - f.D_F * plant.C;
  }
  return f;
}

}  // namespace hinf::synth
