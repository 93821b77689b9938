#include "log_det_barrier.hpp"

#include <cmath>

namespace hinf::sdp {

// κ of the spectral split in factor_jacobian: round-off of the explicit part ε·κ² ≈ 2e-8.
constexpr double kJacobianSplit = 1e4;

LogDetBarrier::LogDetBarrier(const lmi::LmiProblem& lmi, Eigen::VectorXd c, double margin,
                             double radius, bool phase1, double phase1_weight)
    : lmi_(lmi), c_(std::move(c)), margin_(margin), radius_(radius), phase1_(phase1), eta_(phase1_weight),
      n_(lmi.num_params()), N_(lmi.order()) {}

static bool same(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && (a.array() == b.array()).all();
}

bool LogDetBarrier::factor(const Eigen::VectorXd& z) {
  if (have_factor_ && same(z, z_factored_)) return factor_ok_;
  have_factor_ = true;
  have_derivs_ = false;
  z_factored_ = z;
  factor_ok_ = false;
  if (!z.allFinite()) return false;
  const auto x = z.head(n_);
  const double r2 = radius_ * radius_ - x.squaredNorm();
  if (!(r2 > 0)) return false;
  ball_ = std::log(r2);
  slack_ = -lmi_.evaluate(x);
  slack_.diagonal().array() -= margin_;
  if (phase1_) slack_.diagonal().array() += z(n_);
  llt_.compute(slack_);
  if (llt_.info() != Eigen::Success) return false;
  const auto& Lf = llt_.matrixLLT();
  double ld = 0;
  for (int i = 0; i < N_; ++i) {
    const double d = Lf(i, i);
    if (!(d > 0) || !std::isfinite(d)) return false;
    ld += std::log(d);
  }
  logdet_ = 2 * ld;
  factor_ok_ = true;
  return true;
}

double LogDetBarrier::linear_objective(const Eigen::VectorXd& z) const {
  return phase1_ ? z(n_) + eta_ * c_.dot(z.head(n_)) : c_.dot(z.head(n_));
}

Eigen::VectorXd LogDetBarrier::objective_gradient() const {
  Eigen::VectorXd cz = Eigen::VectorXd::Zero(dim());
  if (phase1_) {
    cz.head(n_) = eta_ * c_;
    cz(n_) = 1.0;
  } else {
    cz.head(n_) = c_;
  }
  return cz;
}

bool LogDetBarrier::value(const Eigen::VectorXd& z, double& f) {
  if (!factor(z)) return false;
  f = t_ * linear_objective(z) - logdet_ - ball_;
  return std::isfinite(f);
}

bool LogDetBarrier::derivatives(const Eigen::VectorXd& z) {
  if (!factor(z)) return false;
  if (have_derivs_ && same(z, z_derivs_)) return true;
  const int d = dim();
  W_.setIdentity(N_, N_);
  llt_.solveInPlace(W_);
  for (int j = 0; j < N_; ++j)  // W ← (W + Wᵀ)/2 in place (exactly symmetric)
    for (int i = j + 1; i < N_; ++i) W_(i, j) = W_(j, i) = 0.5 * (W_(i, j) + W_(j, i));
  // ∂φ/∂xᵢ = tr(W Mᵢ) with Mᵢ the derivative of M; the slack is −M, so
  // ∂(−log det slack)/∂xᵢ = tr(slack⁻¹ Mᵢ) = tr(W Mᵢ).
  Eigen::VectorXd gx;
  lmi_.trace_products(W_, gx);
  if (!lmi_.hessian(W_, Hs_, [this] { return beat_and_check_deadline(); })) return false;
  grad_phi_.resize(d);
  hess_.resize(d, d);
  grad_phi_.head(n_) = gx;
  hess_.topLeftCorner(n_, n_) = Hs_;
  if (phase1_) {
    // slack depends on s through +s·I: ∂/∂s = −tr(W), ∂²/∂s² = tr(W W),
    // ∂²/∂xᵢ∂s = tr(W Mᵢ W (−I))·(−1)... = −tr(W² Mᵢ)
    const Eigen::MatrixXd W2 = W_ * W_;
    Eigen::VectorXd gs;
    lmi_.trace_products(W2, gs);
    grad_phi_(n_) = -W_.trace();
    hess_(n_, n_) = W_.squaredNorm();
    hess_.block(0, n_, n_, 1) = -gs;
    hess_.block(n_, 0, 1, n_) = -gs.transpose();
  }
  // feasibility ball: −log(ρ² − ‖x‖²)
  const auto x = z.head(n_);
  const double r2 = radius_ * radius_ - x.squaredNorm();
  grad_phi_.head(n_) += 2.0 / r2 * x;
  add_ball_hessian(x, hess_.topLeftCorner(n_, n_));
  if (past_deadline()) return false;  // before anyone factorises it (seconds at large p)
  z_derivs_ = z;
  have_derivs_ = true;
  hess_factored_ = false;
  return grad_phi_.allFinite() && hess_.allFinite();
}

void LogDetBarrier::add_ball_hessian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                     Eigen::Ref<Eigen::MatrixXd> H) const {
  // ∇²(−log(ρ² − ‖x‖²)) = (2/r²)·I + (4/r⁴)·x xᵀ,  r² = ρ² − ‖x‖²
  const double r2 = radius_ * radius_ - x.squaredNorm();
  H.diagonal().array() += 2.0 / r2;
  H.noalias() += (4.0 / (r2 * r2)) * x * x.transpose();
}

bool LogDetBarrier::gradient(const Eigen::VectorXd& z, Eigen::VectorXd& g) {
  if (!derivatives(z)) return false;
  g = grad_phi_ + t_ * objective_gradient();
  return true;
}

bool LogDetBarrier::hessian(const Eigen::VectorXd& z, Eigen::MatrixXd& H) {
  if (!derivatives(z)) return false;
  H = hess_;
  return true;
}

bool LogDetBarrier::newton_decrement2(const Eigen::VectorXd& z, double& lambda2) {
  Eigen::VectorXd g;
  if (!gradient(z, g)) return false;
  // Near the end of the path the Hessian's condition number grows like t²; a
  // pivoted LDLᵀ still gives the decrement where a plain Cholesky may break down.
  if (!factor_hessian()) return false;
  lambda2 = g.dot(ldlt_.solve(g));
  return std::isfinite(lambda2) && lambda2 >= 0;
}

bool LogDetBarrier::factor_hessian() {
  if (past_deadline()) return false;
  // hess_ changes only when derivatives() recomputes it (it has no t in it): the Newton
  // decrement and the path tangent at the same point share one factorisation.
  if (!hess_factored_) {
    ldlt_.compute(hess_);
    hess_factored_ = true;
  }
  return ldlt_.info() == Eigen::Success;
}

bool LogDetBarrier::path_tangent(const Eigen::VectorXd& z, Eigen::VectorXd& dz) {
  if (!derivatives(z)) return false;
  const Eigen::VectorXd cz = objective_gradient();
  if (!factor_hessian()) return false;
  dz = -ldlt_.solve(cz);
  return dz.allFinite();
}

bool LogDetBarrier::factor_jacobian(const Eigen::VectorXd& z) {
  if (phase1_ || !factor(z)) return false;
  if (have_qr_ && same(z, z_qr_)) return true;
  have_qr_ = false;
  // Split the slack's spectrum, S = Q Λ Qᵀ: the p eigenvalues below λ_max/κ (the part of
  // W = S⁻¹ above κ·w_min, which grows like t) and the rest. With T = Λ^{-1/2} Qᵀ
  // (TᵀT = W), H = Σₖₗ (T Mᵢ Tᵀ)ₖₗ (T Mⱼ Tᵀ)ₖₗ splits into the pairs (k, l) that touch the
  // first part — rows of the scaled Jacobian, taken into the QR — and the rest, H_mod =
  // tr(W_m Mᵢ W_m Mⱼ) with W_m = Σ_{k∉p} q_k q_kᵀ/λ_k, formed explicitly: its round-off,
  // ε·‖W_m‖², is within ε·κ² of its own smallest scale, so it is accurate, and it enters
  // the QR as its factor F (FᵀF = H_mod, pivoted LDLᵀ). QR of [G_p; F] has RᵀR = H, with
  // N·p rows instead of N(N+1)/2.
  eig_.compute(slack_);
  if (eig_.info() != Eigen::Success) return false;
  const Eigen::VectorXd& lam = eig_.eigenvalues();  // ascending
  if (!(lam(0) > 0)) return false;
  int p = 0;
  while (p < N_ && lam(p) < lam(N_ - 1) / kJacobianSplit) ++p;
  const int f = N_ - p;  // rows of T from f on are the small-λ part
  Tsc_.resize(N_, N_);
  for (int j = 0; j < N_; ++j) {
    const int k = j < f ? p + j : j - f;
    Tsc_.row(j) = eig_.eigenvectors().col(k).transpose() / std::sqrt(lam(k));
  }
  const int mp = lmi::LmiProblem::scaled_jacobian_rows(N_, f);
  G_.resize(mp + n_, n_);
  lmi_.scaled_jacobian(Tsc_, G_, f);
  // H_mod, plus the ball's Hessian
  Wm_.noalias() = Tsc_.topRows(f).transpose() * Tsc_.topRows(f);
  if (!lmi_.hessian(Wm_, Hmod_, [this] { return beat_and_check_deadline(); })) return false;
  add_ball_hessian(z.head(n_), Hmod_);
  mod_ldlt_.compute(Hmod_);
  if (mod_ldlt_.info() != Eigen::Success) return false;
  // F = D^{1/2} Lᵀ P  (P H_mod Pᵀ = L D Lᵀ); Fᵀ = Pᵀ L D^{1/2}
  Eigen::MatrixXd Ft = mod_ldlt_.matrixL();
  Ft = Ft * mod_ldlt_.vectorD().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  Ft = mod_ldlt_.transpositionsP().transpose() * Ft;
  G_.bottomRows(n_) = Ft.transpose();
  if (!G_.allFinite() || past_deadline()) return false;
  // in place: only R (the top n rows' upper triangle) is needed, and no copy of G
  Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(G_);
  z_qr_ = z;
  have_qr_ = true;
  return true;
}

bool LogDetBarrier::accurate_newton(const Eigen::VectorXd& z, Eigen::VectorXd& dz, double& lambda2) {
  Eigen::VectorXd g;
  if (!gradient(z, g) || !factor_jacobian(z)) return false;
  const auto R = G_.topRows(n_).triangularView<Eigen::Upper>();  // QR done in place
  Eigen::VectorXd y = R.transpose().solve(g);  // Rᵀy = g
  lambda2 = y.squaredNorm();
  dz = -R.solve(y);
  return dz.allFinite() && std::isfinite(lambda2);
}

bool LogDetBarrier::accurate_path_tangent(const Eigen::VectorXd& z, Eigen::VectorXd& dz) {
  if (!factor_jacobian(z)) return false;
  const auto R = G_.topRows(n_).triangularView<Eigen::Upper>();  // QR done in place
  dz = -R.solve(R.transpose().solve(objective_gradient()));
  return dz.allFinite();
}

}  // namespace hinf::sdp
