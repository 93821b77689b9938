// Generalized (QZ) eigenvalue computations on a real matrix pencil (M, N), i.e. the
// values z with det(M − z N) = 0, via LAPACK (Moler–Stewart QZ; LAPACK Users' Guide
// §2.3.5.2, routines DGGEV and DGGES). Private to the synthesis library.
#pragma once
#include <Eigen/Dense>

namespace hinf::certify::detail {

// Eigenvalues z_i = alpha_i / beta_i of the pencil (M, N). beta_i = 0 marks an infinite
// eigenvalue. Throws Error(NumericalFailure) if the QZ iteration fails.
struct PencilEigenvalues {
  Eigen::VectorXcd alpha;
  Eigen::VectorXd beta;
};
PencilEigenvalues pencil_eigenvalues(const Eigen::MatrixXd& M, const Eigen::MatrixXd& N);

// Ordered real generalized Schur form Qᵀ M Z = S, Qᵀ N Z = T (DGGES with SORT = 'S'),
// with the eigenvalues strictly inside the unit circle (|alpha| < |beta|) first.
// Z's first `stable_count` columns span the stable right deflating subspace.
// `reordering_failed` is set when LAPACK reports INFO = n+2 (roundoff moved an
// eigenvalue across the unit circle during reordering).
struct OrderedQz {
  Eigen::MatrixXd Z;
  Eigen::VectorXcd alpha;
  Eigen::VectorXd beta;
  int stable_count = 0;
  bool reordering_failed = false;
};
OrderedQz ordered_qz_stable_first(const Eigen::MatrixXd& M, const Eigen::MatrixXd& N);

}  // namespace hinf::certify::detail
