// Cholesky factorisation and solves for the filters' small fixed-size matrices (S, the REKF's
// γ²I − L P L^T, the covariance check), written out as plain loops: no dynamic-size blocks,
// no packing, no heap. The order of every operation is that of Eigen 3.4's LLT on a build
// without FMA (llt_inplace::unblocked; triangular_solve_matrix with its panels of
// kSolvePanelWidth rows, each panel's rows below or above it updated by one sum over the
// panel), so the results are Eigen::LLT's bit for bit (tests/runtime/test_small_cholesky.cpp)
// at about a fifth of the cost (docs/benchmarks.md "Monte-Carlo throughput"). A dynamic size
// falls back to Eigen::LLT itself.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <cmath>

namespace hinf::runtime::detail {

// Eigen's triangular_solve_matrix panel width on SSE2 doubles: max(gebp mr, nr) = 4.
inline constexpr int kSolvePanelWidth = 4;

// A = L L^T in place: L in the lower triangle (the strict upper triangle is left as it was).
// False when a pivot is ≤ 0 — Eigen's LLT NumericalIssue; like Eigen, a NaN pivot is not
// caught here (callers check finiteness first).
template <int N>
bool cholesky_in_place(Eigen::Matrix<double, N, N>& A) {
  static_assert(N != Eigen::Dynamic, "cholesky_in_place: fixed sizes only");
  for (int k = 0; k < N; ++k) {
    double x = A(k, k);
    if (k > 0) {
      double s = A(k, 0) * A(k, 0);
      for (int j = 1; j < k; ++j) s = s + A(k, j) * A(k, j);
      x -= s;
    }
    if (x <= 0.0) return false;
    x = std::sqrt(x);
    A(k, k) = x;
    for (int i = k + 1; i < N; ++i) {
      if (k > 0) {
        double s = A(i, 0) * A(k, 0);
        for (int j = 1; j < k; ++j) s = s + A(i, j) * A(k, j);
        A(i, k) -= s;
      }
      A(i, k) /= x;
    }
  }
  return true;
}

// B ← L^-1 B (L lower triangular, the lower triangle of `L`).
template <int N, int M>
void lower_solve_in_place(const Eigen::Matrix<double, N, N>& L, Eigen::Matrix<double, N, M>& B) {
  for (int k1 = 0; k1 < N; k1 += kSolvePanelWidth) {
    const int end = k1 + kSolvePanelWidth < N ? k1 + kSolvePanelWidth : N;
    for (int i = k1; i < end; ++i) {  // the panel: right-looking, times the reciprocal pivot
      const double a = 1.0 / L(i, i);
      for (int j = 0; j < M; ++j) {
        const double b = (B(i, j) *= a);
        for (int r = i + 1; r < end; ++r) B(r, j) -= b * L(r, i);
      }
    }
    for (int r = end; r < N; ++r)  // the rows below: one sum over the panel each
      for (int j = 0; j < M; ++j) {
        double s = 0.0;  // the kernel's accumulator starts at +0 (the sign of a zero sum)
        for (int k = k1; k < end; ++k) s = s + L(r, k) * B(k, j);
        B(r, j) -= s;
      }
  }
}

// B ← L^-T B.
template <int N, int M>
void upper_solve_in_place(const Eigen::Matrix<double, N, N>& L, Eigen::Matrix<double, N, M>& B) {
  for (int k1 = 0; k1 < N; k1 += kSolvePanelWidth) {
    const int top = N - k1 - kSolvePanelWidth > 0 ? N - k1 - kSolvePanelWidth : 0;  // the panel: rows top … N − k1 − 1
    for (int i = N - k1 - 1; i >= top; --i) {  // left-looking within the panel, from the bottom
      const double a = 1.0 / L(i, i);
      for (int j = 0; j < M; ++j) {
        double b = 0.0;
        for (int r = i + 1; r < N - k1; ++r) b = b + L(r, i) * B(r, j);
        B(i, j) = (B(i, j) - b) * a;
      }
    }
    for (int r = 0; r < top; ++r)  // the rows above: one sum over the panel each
      for (int j = 0; j < M; ++j) {
        double s = 0.0;
        for (int k = top; k < N - k1; ++k) s = s + L(k, r) * B(k, j);
        B(r, j) -= s;
      }
  }
}

// The factorisation of a symmetric positive definite A (its lower triangle), or none.
template <int N>
class SmallLlt {
 public:
  explicit SmallLlt(const Eigen::Matrix<double, N, N>& A) : L_(A) {
    if constexpr (N == Eigen::Dynamic) {
      eigen_.compute(A);
      ok_ = eigen_.info() == Eigen::Success;
    } else {
      ok_ = cholesky_in_place(L_);
    }
  }
  bool ok() const { return ok_; }
  // L^-1 v (a vector: Eigen's own triangular solve, as LLT::matrixL().solve).
  template <class V>
  auto lower_solve(const V& v) const {
    if constexpr (N == Eigen::Dynamic) return Eigen::Matrix<double, N, 1>(eigen_.matrixL().solve(v));
    else return Eigen::Matrix<double, N, 1>(L_.template triangularView<Eigen::Lower>().solve(v));
  }
  // A^-1 B.
  template <int M>
  Eigen::Matrix<double, N, M> solve(const Eigen::Matrix<double, N, M>& B) const {
    if constexpr (N == Eigen::Dynamic) {
      return eigen_.solve(B);
    } else if constexpr (M == 1) {  // a vector: Eigen's vector solves, as LLT::solve takes them
      Eigen::Matrix<double, N, M> X = B;
      L_.template triangularView<Eigen::Lower>().solveInPlace(X);
      L_.transpose().template triangularView<Eigen::Upper>().solveInPlace(X);
      return X;
    } else {
      Eigen::Matrix<double, N, M> X = B;
      lower_solve_in_place(L_, X);
      upper_solve_in_place(L_, X);
      return X;
    }
  }

 private:
  Eigen::Matrix<double, N, N> L_;
  Eigen::LLT<Eigen::Matrix<double, N, N>> eigen_;  // dynamic sizes only
  bool ok_ = false;
};

}  // namespace hinf::runtime::detail
