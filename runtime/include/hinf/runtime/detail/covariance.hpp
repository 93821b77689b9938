// Small helpers for covariance handling; fixed-size, no heap allocation.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Dense>

namespace hinf::runtime::detail {

// P <- (P + P^T) / 2, in place.
template <class Derived>
void symmetrise(Eigen::MatrixBase<Derived>& P) {
  for (Eigen::Index j = 0; j < P.cols(); ++j)
    for (Eigen::Index i = j + 1; i < P.rows(); ++i) {
      const auto s = 0.5 * (P(i, j) + P(j, i));
      P(i, j) = s;
      P(j, i) = s;
    }
}

// Positive definiteness by an attempted Cholesky factorisation (also fails on NaN).
template <class MatrixType>
bool is_positive_definite(const MatrixType& P) {
  if (!P.allFinite()) return false;
  Eigen::LLT<MatrixType> llt(P);
  return llt.info() == Eigen::Success;
}

}  // namespace hinf::runtime::detail
