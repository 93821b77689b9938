// Small helpers for covariance handling; fixed-size, no heap allocation.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include "hinf/runtime/detail/small_cholesky.hpp"

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

// Every entry finite — Eigen's allFinite verdict at a vectorised sum's cost: each entry times
// zero is ±0, or NaN for a NaN or ±∞ one.
template <class Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& M) {
  return (M.array() * 0.0).sum() == 0.0;
}

// Positive definiteness by an attempted Cholesky factorisation (also fails on NaN).
template <class MatrixType>
bool is_positive_definite(const MatrixType& P) {
  if (!all_finite(P)) return false;
  if constexpr (MatrixType::RowsAtCompileTime == Eigen::Dynamic) {
    return Eigen::LLT<MatrixType>(P).info() == Eigen::Success;
  } else {
    Eigen::Matrix<double, MatrixType::RowsAtCompileTime, MatrixType::RowsAtCompileTime> L = P;
    return cholesky_in_place(L);
  }
}

}  // namespace hinf::runtime::detail
