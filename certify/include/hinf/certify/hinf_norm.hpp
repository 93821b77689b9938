// The H∞ norm of a stable discrete-time system G(z) = C (zI − A)⁻¹ B + D,
//   ‖G‖∞ = max_{θ ∈ [0, π]} σ_max(G(e^{jθ})),
// by the two-step algorithm of Bruinsma & Steinbuch ("A fast algorithm to compute the
// H∞-norm of a transfer function matrix", Systems & Control Letters 14, 1990) and
// Boyd & Balakrishnan (1990), in its discrete-time form: γ is a singular value of
// G(e^{jθ}) iff e^{jθ} is an eigenvalue of a symplectic pencil (derived in
// hinf_norm.cpp). No LMI and no frequency grid: the level sets of σ_max are located
// exactly (up to eigenvalue accuracy) and the lower bound is raised at their midpoints.
#pragma once
#include <Eigen/Dense>

#include "hinf/models/state_space.hpp"

namespace hinf::certify {

struct HinfNorm {
  double norm = 0;            // certified upper value: ‖G‖∞ ≤ norm ≤ (1 + rel_tol)‖G‖∞
  double peak_frequency = 0;  // rad/sample in [0, π], where lower_bound is attained
  double lower_bound = 0;     // σ_max(G(e^{j·peak})) ≥ norm/(1 + rel_tol), except when
                              // ‖G‖∞ ≤ (1 + rel_tol)σ_max(D) (then only σ_max(D) ≤ ‖G‖∞
                              // is known; σ_max(D) ≤ ‖G‖∞ by the maximum modulus principle)
  int iterations = 0;         // symplectic-pencil eigenvalue problems solved
};

// Throws Error(InvalidInput) on inconsistent dimensions, non-finite entries or
// rel_tol outside [1e-14, 1); Error(Infeasible) naming the spectral radius if A is not
// Schur stable; Error(NumericalFailure) if the iteration does not terminate.
HinfNorm discrete_hinf_norm(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                            const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                            double rel_tol = 1e-10);
HinfNorm discrete_hinf_norm(const StateSpace& system, double rel_tol = 1e-10);

// ‖G‖∞ of a continuous-time system G(s) = C (sI − A)⁻¹ B + D, by the bilinear map
// s = α (z − 1)/(z + 1), which takes the imaginary axis onto the unit circle and keeps
// the norm (docs/maths.md (152)):
//   A_d = (αI − A)⁻¹(αI + A),  B_d = √(2α)(αI − A)⁻¹B,  C_d = √(2α) C (αI − A)⁻¹,
//   D_d = D + C (αI − A)⁻¹B,
// then discrete_hinf_norm; α is the geometric mean of the smallest and largest pole
// moduli (1 without poles). peak_frequency is in rad/s, ω = α tan(θ/2). Error(Infeasible)
// naming the spectral abscissa if A is not Hurwitz; otherwise as discrete_hinf_norm.
HinfNorm continuous_hinf_norm(const StateSpace& system, double rel_tol = 1e-10);

}  // namespace hinf::certify
