// The H2 norm of a stable discrete-time system (docs/maths.md (132)): the RMS of the output
// under unit-covariance white noise at the input, ‖G‖₂² = tr(C P Cᵀ + D Dᵀ) with the
// controllability Gramian P = A P Aᵀ + B Bᵀ, computed by Smith's doubling
// (P ← P + A P Aᵀ, A ← A², quadratic convergence for ρ(A) < 1).
#pragma once
#include "hinf/models/state_space.hpp"

namespace hinf::certify {

// Throws Error(Infeasible) naming the spectral radius if A is not Schur stable,
// Error(NumericalFailure) if the doubling has not converged after 64 squarings.
double discrete_h2_norm(const StateSpace& system);

}  // namespace hinf::certify
