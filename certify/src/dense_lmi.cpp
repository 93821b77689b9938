#include "hinf/certify/dense_lmi.hpp"

#include <cmath>
#include <vector>

namespace hinf::certify {

using Eigen::MatrixXd;

namespace {
// Fills a symmetric block matrix from its upper-triangular blocks.
class BlockMatrix {
 public:
  explicit BlockMatrix(std::vector<int> sizes) : sizes_(std::move(sizes)) {
    int o = 0;
    for (int s : sizes_) {
      offsets_.push_back(o);
      o += s;
    }
    M_ = MatrixXd::Zero(o, o);
  }
  void set(int r, int c, const MatrixXd& B) {
    M_.block(offsets_[r], offsets_[c], sizes_[r], sizes_[c]) = B;
    if (r != c) M_.block(offsets_[c], offsets_[r], sizes_[c], sizes_[r]) = B.transpose();
  }
  const MatrixXd& matrix() const { return M_; }

 private:
  std::vector<int> sizes_, offsets_;
  MatrixXd M_;
};
}  // namespace

MultiplierTerms multiplier_terms(const hinf::Plant& P, const Eigen::VectorXd& lambda) {
  MultiplierTerms t{MatrixXd::Zero(P.n(), P.n()), MatrixXd::Zero(P.j(), P.j())};
  if (!P.structured()) {
    t.EtLE = lambda(0) * P.E.transpose() * P.E;
    t.Lambda.diagonal().setConstant(lambda(0));
    return t;
  }
  Eigen::Index b = 0;
  for (const auto& [at, size] : P.F_block_ranges()) {
    const MatrixXd Eb = P.E.middleRows(at, size);
    t.EtLE += lambda(b) * Eb.transpose() * Eb;
    t.Lambda.diagonal().segment(at, size).setConstant(lambda(b));
    ++b;
  }
  return t;
}

MatrixXd theorem1_matrix(const hinf::Plant& P, const Theorem1Point& x) {
  const int n = P.n(), p = P.p(), q = P.q(), l = P.l();
  const bool unc = P.uncertain();
  std::vector<int> sizes{n, n, n, n, p, q, l};
  if (unc) sizes.push_back(P.j());
  BlockMatrix M(sizes);
  // docs/maths.md (18), upper triangle, row by row
  M.set(0, 0, -x.R);
  M.set(0, 1, -x.S);
  M.set(0, 2, x.R * P.A + x.BF_bar * P.C);
  M.set(0, 3, x.AF_bar);
  M.set(0, 4, x.R * P.B);
  M.set(0, 5, x.BF_bar * P.D);
  M.set(1, 1, -x.S);
  M.set(1, 2, x.S * P.A + x.BF_bar * P.C);
  M.set(1, 3, x.AF_bar);
  M.set(1, 4, x.S * P.B);
  M.set(1, 5, x.BF_bar * P.D);
  const MultiplierTerms mt = unc ? multiplier_terms(P, x.lambda) : MultiplierTerms{MatrixXd::Zero(n, n), MatrixXd()};
  M.set(2, 2, -x.R + mt.EtLE);
  M.set(2, 3, -x.S);
  M.set(2, 6, P.L.transpose());
  M.set(3, 3, -x.S);
  M.set(3, 6, -x.CF_bar.transpose());
  M.set(4, 4, -x.g * MatrixXd::Identity(p, p));
  M.set(5, 5, -x.g * MatrixXd::Identity(q, q));
  M.set(6, 6, -MatrixXd::Identity(l, l));
  if (unc) {
    M.set(0, 7, x.R * P.H);
    M.set(1, 7, x.S * P.H);
    M.set(7, 7, -mt.Lambda);
  }
  return M.matrix();
}

MatrixXd observer_lmi_matrix(const hinf::Plant& P, const ObserverPoint& x) {
  const int n = P.n(), p = P.p(), q = P.q(), l = P.l();
  const bool unc = P.uncertain();
  std::vector<int> sizes{n, n, p, q, l};
  if (unc) sizes.push_back(P.j());
  BlockMatrix M(sizes);
  // docs/maths.md (124), upper triangle, row by row
  M.set(0, 0, -x.P);
  M.set(0, 1, x.P * P.A - x.Y * P.C);
  M.set(0, 2, x.P * P.B);
  M.set(0, 3, -x.Y * P.D);
  const MultiplierTerms mt = unc ? multiplier_terms(P, x.lambda) : MultiplierTerms{MatrixXd::Zero(n, n), MatrixXd()};
  M.set(1, 1, -x.P + mt.EtLE);
  if (x.N.size() == 0) {
    M.set(1, 4, P.L.transpose());
  } else {  // filtered variant (142): output row (L − N C, 0, −N D)
    M.set(1, 4, (P.L - x.N * P.C).transpose());
    M.set(3, 4, -(x.N * P.D).transpose());
  }
  M.set(2, 2, -x.g * MatrixXd::Identity(p, p));
  M.set(3, 3, -x.g * MatrixXd::Identity(q, q));
  M.set(4, 4, -MatrixXd::Identity(l, l));
  if (unc) {
    M.set(0, 5, x.P * P.H);
    M.set(5, 5, -mt.Lambda);
  }
  return M.matrix();
}

DefinitenessCheck check_negative_definite(const MatrixXd& M, double margin) {
  DefinitenessCheck c;
  const MatrixXd Ms = 0.5 * (M + M.transpose());
  // The large eigenvalues (and ‖M‖₂) come accurately from a symmetric eigensolver, the
  // one nearest zero does not: its absolute error is ~ε‖M‖₂, and M is graded (with a
  // config's H and E far apart in scale, ‖M‖₂ ~ 1e8 against a margin of 1e-9).
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<MatrixXd>(Ms, Eigen::EigenvaluesOnly).eigenvalues();
  const double norm = std::max(std::abs(ev(0)), std::abs(ev(ev.size() - 1)));
  c.max_eig = ev(ev.size() - 1);
  // Definiteness by Cholesky of N = −M − margin·I after Jacobi scaling D^{-1/2} N D^{-1/2}
  // (D = diag N; a congruence, so the inertia is N's — Sylvester). Cholesky's backward
  // error is then relative to each entry's own scale. If it succeeds, the eigenvalue
  // nearest zero is recomputed as −1/λ_max(N⁻¹), N⁻¹ = D^{-1/2} Ñ⁻¹ D^{-1/2}: the
  // largest eigenvalue of N⁻¹ is one a symmetric eigensolver gets to relative accuracy.
  MatrixXd N = -Ms;
  N.diagonal().array() -= margin;
  const Eigen::ArrayXd d = N.diagonal().array();
  if ((d > 0).all() && d.allFinite()) {
    const Eigen::VectorXd r = d.rsqrt().matrix();
    const MatrixXd Nt = r.asDiagonal() * N * r.asDiagonal();
    const Eigen::LLT<MatrixXd> llt(Nt);
    if (llt.info() == Eigen::Success) {
      MatrixXd Ninv = llt.solve(MatrixXd::Identity(N.rows(), N.cols()));
      Ninv = r.asDiagonal() * Ninv * r.asDiagonal();
      const MatrixXd Ninv_sym = 0.5 * (Ninv + Ninv.transpose());
      const double mu =
          Eigen::SelfAdjointEigenSolver<MatrixXd>(Ninv_sym, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
      if (mu > 0 && std::isfinite(mu)) {
        c.max_eig = -1.0 / mu - margin;  // largest eigenvalue of M itself
        c.negative_definite = true;
      }
    }
  }
  c.max_eig_relative = norm > 0 ? c.max_eig / norm : 0.0;
  return c;
}

}  // namespace hinf::certify
