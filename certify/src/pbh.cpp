// unseen_unstable_mode (pbh.hpp).
#include "hinf/certify/pbh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hinf::certify {

std::optional<UnseenMode> unseen_unstable_mode(const Eigen::MatrixXd& A, const Eigen::MatrixXd& X, bool discrete,
                                               double disk_radius) {
  const Eigen::Index n = A.rows();
  const double u = std::numeric_limits<double>::epsilon() / 2;
  Eigen::ComplexEigenSolver<Eigen::MatrixXd> es(A, false);
  const double norm_A = A.norm(), norm_X = X.norm();
  const Eigen::MatrixXcd Xs = X.cast<std::complex<double>>() / (norm_X > 0 ? norm_X : 1.0);
  const auto unseen_at = [&](std::complex<double> lambda) -> std::optional<UnseenMode> {
    const bool stable = discrete ? std::abs(lambda) < 1 : lambda.real() < 0;
    if (stable && std::abs(lambda) < disk_radius) return std::nullopt;
    const Eigen::MatrixXcd shifted = A.cast<std::complex<double>>() - lambda * Eigen::MatrixXcd::Identity(n, n);
    // the shifted block at unit norm, but never magnified beyond 1/√u of the data's scale: where
    // A − λI is that close to 0 (A ≈ λI) its entries are mostly rounding and X decides
    const double data = norm_A + std::abs(lambda);
    const double block = std::max({shifted.norm(), std::sqrt(u) * data, std::numeric_limits<double>::min()});
    Eigen::MatrixXcd pbh(n + X.rows(), n);
    pbh << shifted / block, Xs;
    const double tolerance = kPbhRelativeTolerance + kPbhRoundingFactor * u * data / block;
    const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(pbh, Eigen::ComputeFullV);
    if (svd.singularValues()(n - 1) <= tolerance) return UnseenMode{lambda, svd.matrixV().col(n - 1)};
    return std::nullopt;
  };
  const Eigen::VectorXcd& lambdas = es.eigenvalues();
  for (Eigen::Index i = 0; i < lambdas.size(); ++i) {
    if (const auto m = unseen_at(lambdas(i))) return m;
    // A defective eigenvalue (a Jordan block of size k) is computed as a cluster spread by
    // u^(1/k)·‖A‖ around it, so the test at any one member can miss an unseen mode; the
    // cluster's mean is accurate to O(u‖A‖): tested too (blocks up to size 3).
    const double radius = std::cbrt(u) * (norm_A + std::abs(lambdas(i)));
    std::complex<double> sum = 0;
    int members = 0;
    for (Eigen::Index j = 0; j < lambdas.size(); ++j)
      if (std::abs(lambdas(j) - lambdas(i)) <= radius) sum += lambdas(j), ++members;
    if (members > 1)
      if (const auto m = unseen_at(sum / static_cast<double>(members))) return m;
  }
  return std::nullopt;
}

}  // namespace hinf::certify
