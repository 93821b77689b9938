// unseen_unstable_mode (pbh.hpp).
#include "hinf/certify/pbh.hpp"

#include <algorithm>

namespace hinf::certify {

std::optional<UnseenMode> unseen_unstable_mode(const Eigen::MatrixXd& A, const Eigen::MatrixXd& X, bool discrete) {
  const Eigen::Index n = A.rows();
  Eigen::ComplexEigenSolver<Eigen::MatrixXd> es(A, false);
  Eigen::MatrixXd AX(n + X.rows(), n);
  AX << A, X;
  const double scale = std::max(1.0, AX.norm());
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
    const std::complex<double> lambda = es.eigenvalues()(i);
    if (discrete ? std::abs(lambda) < 1 : lambda.real() < 0) continue;
    Eigen::MatrixXcd pbh(n + X.rows(), n);
    pbh << A.cast<std::complex<double>>() - lambda * Eigen::MatrixXcd::Identity(n, n), X.cast<std::complex<double>>();
    const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(pbh, Eigen::ComputeFullV);
    if (svd.singularValues()(n - 1) <= kPbhRelativeTolerance * scale) return UnseenMode{lambda, svd.matrixV().col(n - 1)};
  }
  return std::nullopt;
}

}  // namespace hinf::certify
