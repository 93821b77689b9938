// The PBH test of docs/maths.md (126): an unstable mode of A that X does not see. With
// X = C it is an undetectable mode (no filter and no controller makes the error or the
// loop stable); with (Aᵀ, B2ᵀ) an unstabilisable one. The pre-flight of the observer-form
// filter and of the controller, one home for both.
#pragma once
#include <Eigen/Dense>
#include <complex>
#include <limits>
#include <optional>

namespace hinf::certify {

// A mode counts as unseen when the PBH matrix with each block brought to unit norm,
// [(A − λI)/s; X/‖X‖] with s = max(‖A − λI‖, √u (‖A‖ + |λ|)), has a singular value below this
// plus the rounding of its data, kPbhRoundingFactor · u · (‖A‖ + |λ|)/s (u the unit
// roundoff; at most 64 √u ≈ 1e-6). Each block at
// its own scale makes the verdict independent of the units of the state's time (A → αA),
// of X (a control in N or in mN) and of the plant's magnitude (entries of 1e-150 or 1e150):
// with the blocks at max(1, ‖[A; X]‖) a stabilisable A = [[0, 1], [0, 1e5]], B2 = [0; 1]
// was declared unstabilisable, and a plant sampled at 1e-10 s undetectable.
inline constexpr double kPbhRelativeTolerance = 1e-10;
inline constexpr double kPbhRoundingFactor = 64;

struct UnseenMode {
  std::complex<double> lambda;  // the eigenvalue of A
  Eigen::VectorXcd direction;   // v, ‖v‖ = 1: (A − λI) v ≈ 0 and X v ≈ 0
};

// The first eigenvalue λ of A (in the eigensolver's order) outside the stability region
// (|λ| ≥ 1 in discrete time, Re λ ≥ 0 in continuous time) or outside the disk |λ| < r of a
// pole-region design (docs/maths.md (153); r = ∞: none) at which [A − λI; X] loses rank, if
// any. A is n×n, X has n columns.
std::optional<UnseenMode> unseen_unstable_mode(const Eigen::MatrixXd& A, const Eigen::MatrixXd& X, bool discrete,
                                               double disk_radius = std::numeric_limits<double>::infinity());

}  // namespace hinf::certify
