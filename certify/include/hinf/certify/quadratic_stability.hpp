// A verified witness that A + H F E is not quadratically stable over ‖F‖ ≤ 1 (docs/maths.md
// §3.7): a point z with |z| ≥ 1 and a vector u at which the uncertainty channel's gain
// ‖E (zI − A)⁻¹ H u‖ / ‖u‖ is proved to exceed 1. Then no P ≻ 0 satisfies the Lyapunov
// inequality for every admissible F, so no filter has a Theorem-1 certificate (eq. (119)).
// The peak frequency comes from the H∞ norm; the gain there is bounded below with every
// rounding error accounted for (a verified inverse bound by the Neumann series).
#pragma once
#include <Eigen/Dense>

namespace hinf::certify {

struct GainWitness {
  bool verified = false;      // gain_lower_bound > 1 is a theorem
  double theta = 0;           // rad/sample of the witness point z ≈ e^{jθ}
  double gain = 0;            // ‖E (zI − A)⁻¹ H‖∞ as computed (upper value, hinf_norm.hpp)
  double gain_lower_bound = 0;  // verified: ‖E (zI − A)⁻¹ H u‖/‖u‖ ≥ this at the witness
};

// A must be Schur stable (Error(Infeasible) otherwise, from the H∞ norm); H is n×k, E is
// j×n. Without uncertainty (k = 0 or j = 0, or H or E zero) the result is not verified.
GainWitness uncertainty_gain_witness(const Eigen::MatrixXd& A, const Eigen::MatrixXd& H, const Eigen::MatrixXd& E);

}  // namespace hinf::certify
