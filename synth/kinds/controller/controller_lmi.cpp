#include "controller_lmi.hpp"

#include <cmath>
#include <string>

#include "hinf/common/error.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;

namespace {

// −γ I on diagonal block b (size k): the variable g, the back-off's fixed γ, or `fixed`.
void add_minus_gamma_identity(ControllerLmi& C, int b, int k, const double* fixed = nullptr) {
  if (fixed) C.lmi.add_constant(b, b, -*fixed * MatrixXd::Identity(k, k));
  else if (C.g_fixed) C.lmi.add_constant(b, b, -*C.g_fixed * MatrixXd::Identity(k, k));
  else C.lmi.add_scalar_term(b, b, C.g, -MatrixXd::Identity(k, k));
}

// The continuous-time bounded-real LMI in the new variables (docs/maths.md (149)), M ≺ 0,
// on the four diagonal blocks from `o` (γ the variable g, or `gamma` when given):
//   [ AS+SAᵀ+B2Ĉ+ĈᵀB2ᵀ   Âᵀ+A+B2D̂C2         B1+B2D̂D21    SC1ᵀ+ĈᵀD12ᵀ         ]
//   [ ∗                  RA+AᵀR+B̂C2+C2ᵀB̂ᵀ   RB1+B̂D21     C1ᵀ+C2ᵀD̂ᵀD12ᵀ        ]
//   [ ∗                  ∗                  −γI           D11ᵀ+D21ᵀD̂ᵀD12ᵀ     ]
//   [ ∗                  ∗                  ∗             −γI                 ]
void continuous_bounded_real(const hinf::GeneralisedPlant& P, ControllerLmi& C, int o, const double* gamma = nullptr) {
  auto& M = C.lmi;
  const int n = P.n();
  const MatrixXd In = MatrixXd::Identity(n, n);
  M.add_term(o, o, C.S, P.A, In, false, /*symmetrize=*/true);
  M.add_term(o, o, C.Chat, P.B2, In, false, true);
  M.add_term(o, o + 1, C.Ahat, In, In, /*transpose=*/true);
  M.add_constant(o, o + 1, P.A);
  M.add_constant(o, o + 2, P.B1);
  M.add_term(o, o + 3, C.S, In, P.C1.transpose());
  M.add_term(o, o + 3, C.Chat, In, P.D12.transpose(), true);
  M.add_term(o + 1, o + 1, C.R, In, P.A, false, true);
  M.add_term(o + 1, o + 1, C.Bhat, In, P.C2, false, true);
  M.add_term(o + 1, o + 2, C.R, In, P.B1);
  M.add_term(o + 1, o + 2, C.Bhat, In, P.D21);
  M.add_constant(o + 1, o + 3, P.C1.transpose());
  add_minus_gamma_identity(C, o + 2, P.nw(), gamma);
  M.add_constant(o + 2, o + 3, P.D11.transpose());
  add_minus_gamma_identity(C, o + 3, P.nz(), gamma);
  if (C.Dhat) {
    M.add_term(o, o + 1, *C.Dhat, P.B2, P.C2);
    M.add_term(o, o + 2, *C.Dhat, P.B2, P.D21);
    M.add_term(o + 1, o + 3, *C.Dhat, P.C2.transpose(), P.D12.transpose(), true);
    M.add_term(o + 2, o + 3, *C.Dhat, P.D21.transpose(), P.D12.transpose(), true);
  }
}

// (149) on blocks 0–3, and −[S I; I R] ≺ 0 as blocks 4, 5.
void continuous_blocks(const hinf::GeneralisedPlant& P, ControllerLmi& C) {
  continuous_bounded_real(P, C, 0);
  const MatrixXd In = MatrixXd::Identity(P.n(), P.n());
  C.lmi.add_term(4, 4, C.S, -In, In);
  C.lmi.add_constant(4, 5, -In);
  C.lmi.add_term(5, 5, C.R, -In, In);
}

// The discrete-time LMI (docs/maths.md (150)) as M ≺ 0, M the negative of
//   [ X   Y   B̄   0  ]      X = [S I; I R],  Y = [AS+B2Ĉ, A+B2D̂C2; Â, RA+B̂C2],
//   [ Yᵀ  X   0   C̄ᵀ ]      B̄ = [B1+B2D̂D21; RB1+B̂D21],  C̄ = [C1S+D12Ĉ, C1+D12D̂C2],
//   [ B̄ᵀ  0   γI  D̄ᵀ ]      D̄ = D11+D12D̂D21,
//   [ 0   C̄   D̄   γI ]
// with X split into its two n-blocks: blocks n, n, n, n, nw, nz.
void discrete_blocks(const hinf::GeneralisedPlant& P, ControllerLmi& C) {
  auto& M = C.lmi;
  const int n = P.n();
  const MatrixXd In = MatrixXd::Identity(n, n);
  for (int b : {0, 2}) {  // the two copies of X
    M.add_term(b, b, C.S, -In, In);
    M.add_constant(b, b + 1, -In);
    M.add_term(b + 1, b + 1, C.R, -In, In);
  }
  M.add_term(0, 2, C.S, -P.A, In);
  M.add_term(0, 2, C.Chat, -P.B2, In);
  M.add_constant(0, 3, -P.A);
  M.add_term(1, 2, C.Ahat, -In, In);
  M.add_term(1, 3, C.R, -In, P.A);
  M.add_term(1, 3, C.Bhat, -In, P.C2);
  M.add_constant(0, 4, -P.B1);
  M.add_term(1, 4, C.R, -In, P.B1);
  M.add_term(1, 4, C.Bhat, -In, P.D21);
  M.add_term(2, 5, C.S, -In, P.C1.transpose());
  M.add_term(2, 5, C.Chat, -In, P.D12.transpose(), true);
  M.add_constant(3, 5, -P.C1.transpose());
  add_minus_gamma_identity(C, 4, P.nw());
  M.add_constant(4, 5, -P.D11.transpose());
  add_minus_gamma_identity(C, 5, P.nz());
  if (C.Dhat) {
    M.add_term(0, 3, *C.Dhat, -P.B2, P.C2);
    M.add_term(0, 4, *C.Dhat, -P.B2, P.D21);
    M.add_term(3, 5, *C.Dhat, -P.C2.transpose(), P.D12.transpose(), true);
    M.add_term(4, 5, *C.Dhat, -P.D21.transpose(), P.D12.transpose(), true);
  }
}

// The disk |λ| < r (Chilali & Gahinet 1996), docs/maths.md (153), in the same variables:
//   [ −r X   Y   ]
//   [  Yᵀ   −r X ]  ≺ 0,   X = [S I; I R],  Y = [AS + B2Ĉ, A + B2D̂C2; Â, RA + B̂C2],
// on the four n-blocks from `first`.
void pole_disk_blocks(const hinf::GeneralisedPlant& P, double r, int first, ControllerLmi& C) {
  auto& M = C.lmi;
  const int n = P.n();
  const MatrixXd In = MatrixXd::Identity(n, n);
  for (int b : {first, first + 2}) {
    M.add_term(b, b, C.S, -r * In, In);
    M.add_constant(b, b + 1, -r * In);
    M.add_term(b + 1, b + 1, C.R, -r * In, In);
  }
  M.add_term(first, first + 2, C.S, P.A, In);
  M.add_term(first, first + 2, C.Chat, P.B2, In);
  M.add_constant(first, first + 3, P.A);
  M.add_term(first + 1, first + 2, C.Ahat, In, In);
  M.add_term(first + 1, first + 3, C.R, In, P.A);
  M.add_term(first + 1, first + 3, C.Bhat, In, P.C2);
  if (C.Dhat) M.add_term(first, first + 3, *C.Dhat, P.B2, P.C2);
}

}  // namespace

namespace {

ControllerLmi build(const hinf::GeneralisedPlant& P, const ControllerDesign& design, std::optional<double> g_fixed,
                    const hinf::UncertaintyChannel* robust = nullptr) {
  const int n = P.n();
  const bool discrete = P.time == hinf::TimeDomain::Discrete;
  std::vector<int> blocks = discrete ? std::vector<int>{n, n, n, n, P.nw(), P.nz()}
                                     : std::vector<int>{n, n, P.nw(), P.nz(), n, n};
  const int disk_first = static_cast<int>(blocks.size());
  if (design.pole_disk_radius) blocks.insert(blocks.end(), {n, n, n, n});
  const int robust_first = static_cast<int>(blocks.size());
  if (robust)
    blocks.insert(blocks.end(), {n, n, static_cast<int>(robust->H.cols()), static_cast<int>(robust->E.rows())});
  ControllerLmi C;
  C.lmi = lmi::LmiProblem(blocks);
  C.g_fixed = g_fixed;
  C.R = C.lmi.add_symmetric("R", n);
  C.S = C.lmi.add_symmetric("S", n);
  C.Ahat = C.lmi.add_full("A_hat", n, n);
  C.Bhat = C.lmi.add_full("B_hat", n, P.ny());
  C.Chat = C.lmi.add_full("C_hat", P.nu(), n);
  if (!design.strictly_proper) C.Dhat = C.lmi.add_full("D_hat", P.nu(), P.ny());
  if (g_fixed) C.t = C.lmi.add_scalar("t");
  else C.g = C.lmi.add_scalar("gamma");
  if (discrete) discrete_blocks(P, C);
  else continuous_blocks(P, C);
  if (design.pole_disk_radius) pole_disk_blocks(P, *design.pole_disk_radius, disk_first, C);
  if (robust) {  // ‖T_qp‖∞ < 1 with the same variables (docs/maths.md (160a))
    const double one = 1;
    continuous_bounded_real(robust_channel_plant(P, *robust), C, robust_first, &one);
  }
  if (g_fixed)  // every diagonal block ≺ t I: minimising t maximises the LMI's margin
    for (int b = 0; b < C.lmi.num_blocks(); ++b)
      C.lmi.add_scalar_term(b, b, *C.t, -MatrixXd::Identity(C.lmi.block_size(b), C.lmi.block_size(b)));
  return C;
}

}  // namespace

ControllerLmi build_controller_lmi(const hinf::GeneralisedPlant& P, const ControllerDesign& design) {
  return build(P, design, std::nullopt);
}

ControllerLmi build_controller_backoff_lmi(const hinf::GeneralisedPlant& P, const ControllerDesign& design,
                                           double g_fixed, const hinf::UncertaintyChannel* robust) {
  return build(P, design, g_fixed, robust);
}

ControllerLmi build_robust_controller_lmi(const hinf::GeneralisedPlant& P, const ControllerDesign& design,
                                          const hinf::UncertaintyChannel& robust) {
  return build(P, design, std::nullopt, &robust);
}

hinf::GeneralisedPlant robust_channel_plant(const hinf::GeneralisedPlant& P, const hinf::UncertaintyChannel& c) {
  hinf::GeneralisedPlant Q = P;
  Q.B1 = c.H;
  Q.C1 = c.E;
  Q.D11 = MatrixXd::Zero(c.E.rows(), c.H.cols());
  Q.D12 = MatrixXd::Zero(c.E.rows(), P.nu());
  Q.D21 = MatrixXd::Zero(P.ny(), c.H.cols());
  return Q;
}

ControllerPoint controller_point(const ControllerLmi& C, const hinf::GeneralisedPlant& P, const Eigen::VectorXd& x) {
  ControllerPoint pt;
  pt.R = C.lmi.value(C.R, x);
  pt.S = C.lmi.value(C.S, x);
  pt.Ahat = C.lmi.value(C.Ahat, x);
  pt.Bhat = C.lmi.value(C.Bhat, x);
  pt.Chat = C.lmi.value(C.Chat, x);
  pt.Dhat = C.Dhat ? C.lmi.value(*C.Dhat, x) : MatrixXd::Zero(P.nu(), P.ny());
  pt.gamma = C.g_fixed ? *C.g_fixed : C.lmi.value(C.g, x)(0, 0);
  return pt;
}

hinf::Controller recover_controller(const ControllerPoint& pt, const hinf::GeneralisedPlant& P, double* cond_N) {
  const int n = P.n();
  const MatrixXd I_RS = MatrixXd::Identity(n, n) - pt.R * pt.S;
  const Eigen::JacobiSVD<MatrixXd> svd(I_RS, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd sigma = svd.singularValues();
  if (!(sigma(n - 1) > sigma(0) * 1e-15))
    throw Error(ErrorCode::NumericalFailure,
                "controller recovery: I - R S is numerically singular (condition number " +
                    std::to_string(sigma(0) / sigma(n - 1)) + "): no controller can be recovered");
  const Eigen::VectorXd root = sigma.cwiseSqrt();
  const MatrixXd N = svd.matrixU() * root.asDiagonal();
  const MatrixXd M = svd.matrixV() * root.asDiagonal();
  if (cond_N) *cond_N = root(0) / root(n - 1);
  // N⁻¹ X = Σ^-½ Uᵀ X and X M⁻ᵀ = X V Σ^-½ (U, V orthogonal)
  const Eigen::VectorXd inv_root = root.cwiseInverse();
  const auto N_inv = [&](const MatrixXd& X) -> MatrixXd { return inv_root.asDiagonal() * (svd.matrixU().transpose() * X); };
  const auto times_M_inv_T = [&](const MatrixXd& X) -> MatrixXd { return (X * svd.matrixV()) * inv_root.asDiagonal(); };
  hinf::Controller K;
  K.D_K = pt.Dhat;
  K.C_K = times_M_inv_T(pt.Chat - K.D_K * P.C2 * pt.S);
  K.B_K = N_inv(pt.Bhat - pt.R * P.B2 * K.D_K);
  K.A_K = N_inv(times_M_inv_T(pt.Ahat - pt.R * (P.A + P.B2 * K.D_K * P.C2) * pt.S - N * K.B_K * P.C2 * pt.S -
                              pt.R * P.B2 * K.C_K * M.transpose()));
  return K;
}

}  // namespace hinf::synth
