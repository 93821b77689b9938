#include "theorem1.hpp"

#include <cmath>
#include <limits>

#include "hinf/certify/error_system.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;
using hinf::Filter;
using hinf::Plant;

namespace {
Theorem1Lmi build(const Plant& P, const double* g_fixed) {
  const int n = P.n(), p = P.p(), q = P.q(), l = P.l(), m = P.m();
  const bool unc = P.uncertain();
  std::vector<int> blocks{n, n, n, n, p, q, l};
  if (unc) blocks.push_back(P.j());
  Theorem1Lmi T;
  T.lmi = lmi::LmiProblem(blocks);
  auto& M = T.lmi;  // M(x), docs/maths.md (18)
  T.R = M.add_symmetric("R", n);
  T.S = M.add_symmetric("S", n);
  T.AFbar = M.add_full("AF_bar", n, n);
  T.BFbar = M.add_full("BF_bar", n, m);
  T.CFbar = M.add_full("CF_bar", l, n);
  if (unc) T.lambda = declare_multipliers(M, P);
  if (!g_fixed) T.g = M.add_scalar("gamma_squared");
  else T.margin = M.add_scalar("margin");

  const MatrixXd In = MatrixXd::Identity(n, n);
  const MatrixXd& Hs = P.H;
  // row 1:  [ −R  −S  RA+B̄_F C  Ā_F  RB  B̄_F D  0  RH ]
  M.add_term(0, 0, T.R, -In, In);
  M.add_term(0, 1, T.S, -In, In);
  M.add_term(0, 2, T.R, In, P.A);
  M.add_term(0, 2, T.BFbar, In, P.C);
  M.add_term(0, 3, T.AFbar, In, In);
  M.add_term(0, 4, T.R, In, P.B);
  M.add_term(0, 5, T.BFbar, In, P.D);
  if (unc) M.add_term(0, 7, T.R, In, Hs);
  // row 2:  [ ∗  −S  SA+B̄_F C  Ā_F  SB  B̄_F D  0  SH ]
  M.add_term(1, 1, T.S, -In, In);
  M.add_term(1, 2, T.S, In, P.A);
  M.add_term(1, 2, T.BFbar, In, P.C);
  M.add_term(1, 3, T.AFbar, In, In);
  M.add_term(1, 4, T.S, In, P.B);
  M.add_term(1, 5, T.BFbar, In, P.D);
  if (unc) M.add_term(1, 7, T.S, In, Hs);
  // row 3:  [ ∗  ∗  −R+λEᵀE  −S  0  0  Lᵀ  0 ]
  M.add_term(2, 2, T.R, -In, In);
  if (unc) add_multiplier_EtE(M, P, T.lambda, P.E, 2);
  M.add_term(2, 3, T.S, -In, In);
  M.add_constant(2, 6, P.L.transpose());
  // row 4:  [ ∗  ∗  ∗  −S  0  0  −C̄_Fᵀ  0 ]
  M.add_term(3, 3, T.S, -In, In);
  M.add_term(3, 6, T.CFbar, -In, MatrixXd::Identity(l, l), /*transpose=*/true);
  // rows 5–8: −gI, −gI, −I, −λI
  add_filter_lmi_tail(M, P, g_fixed, T.g, T.margin, T.lambda, 4);
  return T;
}
}  // namespace

Theorem1Lmi build_theorem1(const Plant& P) { return build(P, nullptr); }

Theorem1Lmi build_theorem1_backoff(const Plant& P, double g_fixed) { return build(P, &g_fixed); }

std::vector<lmi::VarId> declare_multipliers(lmi::LmiProblem& M, const Plant& P) {
  if (!P.structured()) return {M.add_scalar("lambda")};
  std::vector<lmi::VarId> lambda;
  for (std::size_t b = 0; b < P.F_blocks.size(); ++b) lambda.push_back(M.add_scalar("lambda_" + std::to_string(b + 1)));
  return lambda;
}

void add_multiplier_EtE(lmi::LmiProblem& M, const Plant& P, const std::vector<lmi::VarId>& lambda, const MatrixXd& E,
                        int e_block) {
  if (!P.structured()) {
    M.add_scalar_term(e_block, e_block, lambda[0], E.transpose() * E);
    return;
  }
  std::size_t b = 0;
  for (const auto& [at, size] : P.F_block_ranges()) {
    const MatrixXd Eb = E.middleRows(at, size);
    M.add_scalar_term(e_block, e_block, lambda[b++], Eb.transpose() * Eb);
  }
}

void add_multiplier_identity(lmi::LmiProblem& M, const Plant& P, const std::vector<lmi::VarId>& lambda, int h_block) {
  if (!P.structured()) {
    M.add_scalar_term(h_block, h_block, lambda[0], -MatrixXd::Identity(P.j(), P.j()));
    return;
  }
  std::size_t b = 0;
  for (const auto& [at, size] : P.F_block_ranges()) {
    MatrixXd I = MatrixXd::Zero(P.j(), P.j());
    I.diagonal().segment(at, size).setConstant(-1.0);
    M.add_scalar_term(h_block, h_block, lambda[b++], I);
  }
}

void add_filter_lmi_tail(lmi::LmiProblem& M, const Plant& P, const double* g_fixed, lmi::VarId g, lmi::VarId margin,
                         const std::vector<lmi::VarId>& lambda, int first) {
  const int p = P.p(), q = P.q(), l = P.l();
  if (g_fixed) {
    M.add_constant(first, first, -*g_fixed * MatrixXd::Identity(p, p));
    M.add_constant(first + 1, first + 1, -*g_fixed * MatrixXd::Identity(q, q));
    for (int b = 0; b < M.num_blocks(); ++b)
      M.add_scalar_term(b, b, margin, -MatrixXd::Identity(M.block_size(b), M.block_size(b)));
  } else {
    M.add_scalar_term(first, first, g, -MatrixXd::Identity(p, p));
    M.add_scalar_term(first + 1, first + 1, g, -MatrixXd::Identity(q, q));
  }
  M.add_constant(first + 2, first + 2, -MatrixXd::Identity(l, l));
  if (P.uncertain()) add_multiplier_identity(M, P, lambda, first + 3);
}

Eigen::VectorXd multiplier_values(const lmi::LmiProblem& M, const std::vector<lmi::VarId>& lambda,
                                  const Eigen::VectorXd& x) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(lambda.size()));
  for (std::size_t b = 0; b < lambda.size(); ++b) v(static_cast<Eigen::Index>(b)) = x(M.variable(lambda[b]).offset);
  return v;
}

std::vector<lmi::SparseEntry> rounded_EtE_basis_error(const lmi::LmiProblem& lmi,
                                                     const std::vector<lmi::VarId>& lambda, int block,
                                                     const Plant& plant) {
  std::vector<lmi::SparseEntry> err;
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const auto ranges = plant.structured() ? plant.F_block_ranges()
                                         : std::vector<std::pair<int, int>>{{0, plant.k()}};
  for (std::size_t b = 0; b < lambda.size(); ++b) {
    const MatrixXd Eb = plant.E.middleRows(ranges[b].first, ranges[b].second).cwiseAbs();
    const double k = ranges[b].second + 1;
    const MatrixXd bound = k * u / (1 - k * u) * (1 + 4 * u) * (Eb.transpose() * Eb);
    const int param = lmi.variable(lambda[b]).offset, off = lmi.block_offset(block);
    for (int c = 0; c < plant.n(); ++c)
      for (int r = 0; r <= c; ++r)
        if (bound(r, c) > 0) err.push_back({param, off + r, off + c, bound(r, c)});
  }
  return err;
}

std::vector<lmi::SparseEntry> theorem1_basis_error(const Theorem1Lmi& T, const Plant& plant) {
  if (!plant.uncertain()) return {};
  return rounded_EtE_basis_error(T.lmi, T.lambda, 2, plant);
}

certify::Theorem1Point theorem1_point(const Theorem1Lmi& T, const Plant& /*plant*/, const Eigen::VectorXd& x,
                                      double g) {
  certify::Theorem1Point pt;
  pt.R = T.lmi.value(T.R, x);
  pt.S = T.lmi.value(T.S, x);
  pt.AF_bar = T.lmi.value(T.AFbar, x);
  pt.BF_bar = T.lmi.value(T.BFbar, x);
  pt.CF_bar = T.lmi.value(T.CFbar, x);
  pt.lambda = multiplier_values(T.lmi, T.lambda, x);
  pt.g = g;
  return pt;
}

Filter recover_filter(const certify::Theorem1Point& pt) {
  const Eigen::LLT<MatrixXd> S(pt.S);
  if (S.info() != Eigen::Success)
    throw Error(ErrorCode::NumericalFailure, "recovery: S is not positive definite at the solution");
  Filter f;
  f.A_F = S.solve(pt.AF_bar);
  f.B_F = S.solve(pt.BF_bar);
  f.C_F = pt.CF_bar;
  return f;
}

AnalysisLmi build_analysis_lmi(const Plant& P, const Filter& F) {
  const int n = P.n(), p = P.p(), q = P.q(), l = P.l();
  const bool unc = P.uncertain();
  const StateSpace es = certify::error_system(P, F);  // Ā, B̄, C̄, D̄: docs/maths.md (9)–(11), (122)–(123), (141)
  const int n2 = static_cast<int>(es.A.rows());        // 2n, or n for an observer-form filter
  const MatrixXd& A0 = es.A;
  const MatrixXd& Bb = es.B;
  const MatrixXd& Cb = es.C;
  std::vector<int> blocks{n2, n2, p + q, l};
  if (unc) blocks.push_back(P.j());
  AnalysisLmi A;
  A.lmi = lmi::LmiProblem(blocks);
  auto& M = A.lmi;  // M(x), docs/maths.md (50)
  A.P = M.add_symmetric("P", n2);
  if (unc) A.lambda = declare_multipliers(M, P);
  A.g = M.add_scalar("gamma_squared");
  const MatrixXd I2 = MatrixXd::Identity(n2, n2);
  M.add_term(0, 0, A.P, -I2, I2);
  M.add_term(0, 1, A.P, I2, A0);
  M.add_term(0, 2, A.P, I2, Bb);
  M.add_term(1, 1, A.P, -I2, I2);
  M.add_constant(1, 3, Cb.transpose());
  if (!es.D.isZero(0.0)) M.add_constant(2, 3, es.D.transpose());  // the filtered estimate's feedthrough (141)
  M.add_scalar_term(2, 2, A.g, -MatrixXd::Identity(p + q, p + q));
  M.add_constant(3, 3, -MatrixXd::Identity(l, l));
  if (unc) {
    MatrixXd Hb = MatrixXd::Zero(n2, P.j());
    Hb.topRows(n) = P.H;
    MatrixXd Eb = MatrixXd::Zero(P.k(), n2);
    Eb.leftCols(n) = P.E;
    M.add_term(0, 4, A.P, I2, Hb);
    add_multiplier_EtE(M, P, A.lambda, Eb, 1);
    add_multiplier_identity(M, P, A.lambda, 4);
  }
  return A;
}

}  // namespace hinf::synth
