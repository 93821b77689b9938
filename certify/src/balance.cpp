// Diagonal balancing (docs/maths.md §4.4); see balance.hpp.
#include "hinf/certify/balance.hpp"

#include <cmath>

#include "hinf/common/error.hpp"

namespace hinf::certify {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {
// LAPACK xGEBAL's constants: radix 2, a sweep changes a scale only if it lowers the sum of
// the row and column norms below this fraction, and at most this many sweeps.
constexpr double kRadix = 2.0;
constexpr double kImprovement = 0.95;
constexpr int kMaxSweeps = 200;
// Scales stay within 2^±kMaxExponent (no overflow of D⁻¹AD for any finite input).
constexpr double kMaxExponent = 400;

// Off-diagonal 2-norms of column i of [A; Out] and row i of [A, In]. An empty In or Out is
// not indexed: Eigen's row/column of a matrix without storage offsets a null pointer
// (undefined behaviour that clang's UBSan reports).
void norms(const MatrixXd& A, const MatrixXd& In, const MatrixXd& Out, int i, double& c, double& r) {
  const double out = Out.size() > 0 ? Out.col(i).squaredNorm() : 0.0;
  const double in = In.size() > 0 ? In.row(i).squaredNorm() : 0.0;
  c = std::sqrt(std::max(0.0, A.col(i).squaredNorm() - A(i, i) * A(i, i)) + out);
  r = std::sqrt(std::max(0.0, A.row(i).squaredNorm() - A(i, i) * A(i, i)) + in);
}
}  // namespace

VectorXd balancing_scaling(const MatrixXd& A0, const MatrixXd& In0, const MatrixXd& Out0) {
  const int n = static_cast<int>(A0.rows());
  MatrixXd A = A0, In = In0.rows() == n ? In0 : MatrixXd(n, 0), Out = Out0.cols() == n ? Out0 : MatrixXd(0, n);
  VectorXd d = VectorXd::Ones(n);
  if (!A.allFinite() || !In.allFinite() || !Out.allFinite()) return d;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      double c, r;
      norms(A, In, Out, i, c, r);
      if (c == 0 || r == 0) continue;
      const double s = c + r;
      double f = 1, g = r / kRadix;
      while (c < g && std::abs(std::log2(d(i) * f)) < kMaxExponent) f *= kRadix, c *= kRadix, r /= kRadix, g /= kRadix;
      g = c / kRadix;
      while (g >= r && std::abs(std::log2(d(i) * f)) < kMaxExponent) f /= kRadix, c /= kRadix, g /= kRadix, r *= kRadix;
      if (c + r >= kImprovement * s) continue;
      // D⁻¹AD with D_ii ← f·D_ii: column i times f, row i divided by f
      d(i) *= f;
      A.col(i) *= f;
      A.row(i) /= f;
      if (Out.size() > 0) Out.col(i) *= f;  // (never a row or column of an empty matrix: norms())
      if (In.size() > 0) In.row(i) /= f;
      changed = true;
    }
    if (!changed) break;
  }
  return d;
}

Eigen::VectorXcd balanced_eigenvalues(const MatrixXd& A) {
  const VectorXd d = balancing_scaling(A, MatrixXd(), MatrixXd());
  const MatrixXd B = d.cwiseInverse().asDiagonal() * A * d.asDiagonal();
  const Eigen::EigenSolver<MatrixXd> es(B, false);
  if (es.info() != Eigen::Success)
    throw Error(ErrorCode::NumericalFailure, "eigenvalues: the iteration did not converge");
  return es.eigenvalues();
}

}  // namespace hinf::certify
