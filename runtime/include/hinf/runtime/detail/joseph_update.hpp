// Shared measurement update for Ekf and Rekf: gain by Cholesky solves, Joseph form,
// symmetrised. Fixed-size, no heap allocation.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "hinf/runtime/detail/covariance.hpp"
#include "hinf/runtime/filter_status.hpp"

namespace hinf::runtime::detail {

// Given the prior covariance Pbar (P(k|k-1) for the EKF, M(P(k|k-1)) for the REKF),
// the measurement Jacobian H, the effective measurement-noise covariance Rbar (R, or
// gamma^2 C C^T + R) and the innovation nu:
//     S = H Pbar H^T + Rbar                        (symmetrised, Cholesky S = L L^T)
//     NIS = nu^T S^-1 nu = |L^-1 nu|^2
//     K = Pbar H^T S^-1  computed as  K^T = S^-1 (H Pbar)   (Pbar symmetric)
//     x <- x + K nu                  (or the model's x ⊞ K nu: `correct`, kalman_core.hpp)
//     P <- (I - K H) Pbar (I - K H)^T + K Rbar K^T      (Joseph form), symmetrised
// On failure (S not PD, or NIS above gate) x and P are untouched.
// x has NS ≥ NX entries when the model's state is not its error (kalman_core.hpp); only
// `correct` touches it.
template <int NX, int NZ, class Correct, class StateVector>
FilterStatus joseph_update(StateVector& x, Eigen::Matrix<double, NX, NX>& P,
                           const Eigen::Matrix<double, NX, NX>& Pbar, const Eigen::Matrix<double, NZ, NX>& H,
                           const Eigen::Matrix<double, NZ, NZ>& Rbar, const Eigen::Matrix<double, NZ, 1>& nu,
                           double nis_gate, double& nis, Eigen::Matrix<double, NZ, NZ>& S,
                           Eigen::Matrix<double, NX, NZ>& K, Correct&& correct) {
  const Eigen::Matrix<double, NZ, NX> HP = H * Pbar;
  S.noalias() = HP * H.transpose();
  S += Rbar;
  symmetrise(S);
  if (!all_finite(S)) return FilterStatus::InnovationCovarianceNotPD;
  const SmallLlt<NZ> llt(S);
  if (!llt.ok()) return FilterStatus::InnovationCovarianceNotPD;
  nis = llt.lower_solve(nu).squaredNorm();
  if (nis > nis_gate) return FilterStatus::InnovationRejected;
  K = llt.solve(HP).transpose();
  correct(x, K, nu);
  Eigen::Matrix<double, NX, NX> IKH = Eigen::Matrix<double, NX, NX>::Identity(Pbar.rows(), Pbar.cols());
  IKH.noalias() -= K * H;
  const Eigen::Matrix<double, NX, NX> IKHP = IKH * Pbar;
  P.noalias() = IKHP * IKH.transpose();
  const Eigen::Matrix<double, NX, NZ> KR = K * Rbar;
  P.noalias() += KR * K.transpose();
  symmetrise(P);
  return FilterStatus::Ok;
}

// The covariance policy after a step (see filter_status.hpp).
template <int NX>
FilterStatus apply_covariance_policy(Eigen::Matrix<double, NX, NX>& P, const Eigen::Matrix<double, NX, NX>& P0,
                                     CovariancePolicy policy) {
  if (is_positive_definite(P)) return FilterStatus::Ok;
  if (policy == CovariancePolicy::ResetToP0) {
    P = P0;
    return FilterStatus::CovarianceReset;
  }
  return FilterStatus::CovarianceNotPD;
}

// Construction-time validation helpers (throw std::invalid_argument).
template <class Derived>
void require_finite_symmetric(const Eigen::MatrixBase<Derived>& M, const char* owner, const char* name) {
  if (!M.allFinite()) throw std::invalid_argument(std::string(owner) + ": " + name + " has a non-finite entry");
  const double scale = std::max(1.0, M.cwiseAbs().maxCoeff());
  if ((M - M.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale)
    throw std::invalid_argument(std::string(owner) + ": " + name + " is not symmetric");
}

template <class MatrixType>
void require_positive_definite(const MatrixType& M, const char* owner, const char* name) {
  require_finite_symmetric(M, owner, name);
  if (!is_positive_definite(MatrixType(0.5 * (M + M.transpose()))))
    throw std::invalid_argument(std::string(owner) + ": " + name + " is not positive definite (Cholesky failed)");
}

template <class MatrixType>
void require_positive_semidefinite(const MatrixType& M, const char* owner, const char* name) {
  require_finite_symmetric(M, owner, name);
  Eigen::SelfAdjointEigenSolver<MatrixType> es(MatrixType(0.5 * (M + M.transpose())), Eigen::EigenvaluesOnly);
  const double scale = std::max(1.0, M.cwiseAbs().maxCoeff());
  if (es.eigenvalues().minCoeff() < -1e-12 * scale)
    throw std::invalid_argument(std::string(owner) + ": " + name + " is not positive semidefinite (smallest eigenvalue " +
                                std::to_string(es.eigenvalues().minCoeff()) + ")");
}

}  // namespace hinf::runtime::detail
