// Hessenberg-based frequency response (Laub 1981); see frequency_response.hpp.
#include "frequency_response.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <utility>

namespace hinf::certify::detail {

FrequencyResponse::FrequencyResponse(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                     const Eigen::MatrixXd& C, const Eigen::MatrixXd& D)
    : D_(D.cast<std::complex<double>>()) {
  if (A.rows() > 0) {
    Eigen::HessenbergDecomposition<Eigen::MatrixXd> hess(A);
    const Eigen::MatrixXd Q = hess.matrixQ();
    const Eigen::MatrixXd H = hess.matrixH();
    H_ = H.cast<std::complex<double>>();
    QtB_ = (Q.transpose() * B).cast<std::complex<double>>();
    CQ_ = (C * Q).cast<std::complex<double>>();
  } else {
    H_.resize(0, 0);
    QtB_.resize(0, B.cols());
    CQ_.resize(C.rows(), 0);
  }
}

Eigen::MatrixXcd FrequencyResponse::at(double theta) const {
  using cd = std::complex<double>;
  const Eigen::Index n = H_.rows();
  const cd z = std::polar(1.0, theta);
  // Solve (zI − H) X = QᵀB by Gaussian elimination with partial pivoting; the matrix
  // is upper Hessenberg, so each step eliminates one subdiagonal entry.
  Eigen::MatrixXcd M = -H_;
  M.diagonal().array() += z;
  Eigen::MatrixXcd X = QtB_;
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    if (std::abs(M(k + 1, k)) > std::abs(M(k, k))) {
      M.row(k).segment(k, n - k).swap(M.row(k + 1).segment(k, n - k));
      X.row(k).swap(X.row(k + 1));
    }
    if (M(k, k) == cd(0)) continue;  // singular; caught at back substitution
    const cd f = M(k + 1, k) / M(k, k);
    M.row(k + 1).segment(k + 1, n - k - 1) -= f * M.row(k).segment(k + 1, n - k - 1);
    M(k + 1, k) = 0;
    X.row(k + 1) -= f * X.row(k);
  }
  for (Eigen::Index k = n - 1; k >= 0; --k) {
    if (M(k, k) == cd(0)) {
      return Eigen::MatrixXcd::Constant(D_.rows(), D_.cols(),
                                        cd(std::numeric_limits<double>::infinity(), 0));
    }
    if (k + 1 < n) X.row(k) -= M.row(k).segment(k + 1, n - k - 1) * X.bottomRows(n - k - 1);
    X.row(k) /= M(k, k);
  }
  return CQ_ * X + D_;
}

double FrequencyResponse::sigma_max(double theta) const {
  const Eigen::MatrixXcd G = at(theta);
  if (G.size() == 0) return 0.0;
  if (!G.allFinite()) return std::numeric_limits<double>::infinity();
  // σ_max² = λ_max of the smaller Gram matrix (relative accuracy O(ε) for σ_max).
  const Eigen::MatrixXcd gram =
      G.rows() <= G.cols() ? Eigen::MatrixXcd(G * G.adjoint()) : Eigen::MatrixXcd(G.adjoint() * G);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(gram, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, es.eigenvalues()(gram.rows() - 1)));
}

}  // namespace hinf::certify::detail
