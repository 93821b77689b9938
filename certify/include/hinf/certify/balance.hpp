// Diagonal balancing by powers of two (docs/maths.md §4.4, eqs. (108)–(109)): the Osborne
// iteration of LAPACK's xGEBAL, in the system form of SLICOT's TB01ID that scales only the
// states of  [A  In; Out  0]. With d a vector of powers of two, D⁻¹AD, D⁻¹·In and Out·D are
// exact in floating point, so the balanced problem is the same problem, only better
// conditioned for eigenvalue and LMI computations; Eigen's eigensolvers do not balance.
#pragma once
#include <Eigen/Dense>

namespace hinf::certify {

// d (powers of two, n = A.rows()) that make, for every state i, the 2-norms of column i of
// [D⁻¹AD; Out·D] and of row i of [D⁻¹AD, D⁻¹·In] (diagonal of A excluded) agree within a
// factor of 2 or stop improving their sum (LAPACK's 0.95 rule). In (n×·) and Out (·×n) may
// have no columns/rows.
Eigen::VectorXd balancing_scaling(const Eigen::MatrixXd& A, const Eigen::MatrixXd& In, const Eigen::MatrixXd& Out);

// The eigenvalues of A computed on D⁻¹AD, d = balancing_scaling(A, ∅, ∅).
Eigen::VectorXcd balanced_eigenvalues(const Eigen::MatrixXd& A);

}  // namespace hinf::certify
