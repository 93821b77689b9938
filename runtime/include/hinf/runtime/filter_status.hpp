// Status reporting and the covariance policy shared by Ekf and Rekf (docs/maths.md [D15]).
//
// Every predict()/update() returns a FilterStatus; nothing aborts, nothing is hidden.
//
// Policy (documented contract):
//  * NonFiniteInput: u or y has a NaN/Inf entry. The step is skipped; x and P unchanged.
//  * ModelNotFinite: f, F, h or H evaluated to NaN/Inf (e.g. range-azimuth-elevation at
//    zero range). The step is skipped; x and P unchanged.
//  * InnovationCovarianceNotPD: the Cholesky factorisation of the innovation covariance
//    S failed. The update is skipped; x and P unchanged.
//  * InnovationRejected: the normalised innovation squared (NIS) exceeded the configured
//    gate (default: no gate). The update is skipped; x and P unchanged; nis() holds the value.
//  * CovarianceNotPD / CovarianceReset: after a step, the (symmetrised) P failed its
//    Cholesky factorisation. With CovariancePolicy::Report, P is kept as computed and
//    CovarianceNotPD returned; with CovariancePolicy::ResetToP0, P is replaced by the P0
//    given to init() (x is kept) and CovarianceReset returned.
//  * GammaConditionViolated (Rekf only): gamma^2 I - L P L^T is not positive definite,
//    so M(P) does not exist (docs/maths.md (99)). The step is skipped; x and P unchanged; the
//    smallest eigenvalue of gamma^2 I - L P L^T is available from the filter.
//  * FadingFactorCapped / FadingTraceGuard (AugmentedEkf with StrongTracking only): the step
//    was taken, with a fading factor held at its cap λ_max, or with every factor 1 because
//    Σ α_i M_ii ≤ 0 (docs/maths.md (211)).
//  * StateNotFinite (AugmentedEkf): the step produced a non-finite x or P; it is undone and
//    the filter stopped: every later step returns Stopped and changes nothing.
#pragma once

namespace hinf::runtime {

enum class FilterStatus {
  Ok = 0,
  NonFiniteInput,
  ModelNotFinite,
  InnovationCovarianceNotPD,
  InnovationRejected,
  CovarianceNotPD,
  CovarianceReset,
  GammaConditionViolated,
  FadingFactorCapped,
  FadingTraceGuard,
  StateNotFinite,
  Stopped,
};

// The REKF reports through the same enum (RekfStatus::GammaConditionViolated etc.).
using RekfStatus = FilterStatus;

enum class CovariancePolicy {
  Report,     // keep the non-PD P, return CovarianceNotPD
  ResetToP0,  // replace P by P0, return CovarianceReset
};

inline const char* to_string(FilterStatus s) {
  switch (s) {
    case FilterStatus::Ok: return "ok";
    case FilterStatus::NonFiniteInput: return "non-finite input (step skipped)";
    case FilterStatus::ModelNotFinite: return "model or Jacobian not finite (step skipped)";
    case FilterStatus::InnovationCovarianceNotPD: return "innovation covariance not positive definite (update skipped)";
    case FilterStatus::InnovationRejected: return "innovation rejected by the NIS gate (update skipped)";
    case FilterStatus::CovarianceNotPD: return "covariance not positive definite";
    case FilterStatus::CovarianceReset: return "covariance not positive definite; reset to P0";
    case FilterStatus::GammaConditionViolated: return "gamma^2 I - L P L^T not positive definite (step skipped)";
    case FilterStatus::FadingFactorCapped: return "a strong-tracking fading factor reached lambda_max (step taken)";
    case FilterStatus::FadingTraceGuard: return "sum of alpha_i M_ii not positive: fading factors set to 1 (step taken)";
    case FilterStatus::StateNotFinite: return "the step made x or P non-finite: undone, the filter is stopped";
    case FilterStatus::Stopped: return "the filter is stopped after a non-finite state (step skipped)";
  }
  return "unknown";
}

}  // namespace hinf::runtime
