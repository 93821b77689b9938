#include "certify/dense_lmi.hpp"

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

MatrixXd theorem1_matrix(const synth::Plant& P, const Theorem1Point& x) {
  const int n = P.n(), p = P.p(), q = P.q(), l = P.l();
  const bool unc = P.uncertain();
  std::vector<int> sizes{n, n, n, n, p, q, l};
  if (unc) sizes.push_back(P.j());
  BlockMatrix M(sizes);
  // SPEC (20), upper triangle, row by row
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
  M.set(2, 2, -x.R + (unc ? MatrixXd(x.lambda * P.E.transpose() * P.E) : MatrixXd::Zero(n, n)));
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
    M.set(7, 7, -x.lambda * MatrixXd::Identity(P.j(), P.j()));
  }
  return M.matrix();
}

DefinitenessCheck check_negative_definite(const MatrixXd& M, double margin) {
  DefinitenessCheck c;
  const Eigen::VectorXd ev =
      Eigen::SelfAdjointEigenSolver<MatrixXd>(0.5 * (M + M.transpose()), Eigen::EigenvaluesOnly).eigenvalues();
  c.max_eig = ev(ev.size() - 1);
  const double norm = std::max(std::abs(ev(0)), std::abs(ev(ev.size() - 1)));
  c.max_eig_relative = norm > 0 ? c.max_eig / norm : 0.0;
  MatrixXd N = -0.5 * (M + M.transpose());
  N.diagonal().array() -= margin;
  Eigen::LLT<MatrixXd> llt(N);
  c.negative_definite = llt.info() == Eigen::Success && c.max_eig < 0;
  return c;
}

}  // namespace hinf::certify
