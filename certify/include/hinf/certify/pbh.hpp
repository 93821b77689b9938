// The PBH test of docs/maths.md (126): an unstable mode of A that X does not see. With
// X = C it is an undetectable mode (no filter and no controller makes the error or the
// loop stable); with (Aᵀ, B2ᵀ) an unstabilisable one. The pre-flight of the observer-form
// filter and of the controller, one home for both.
#pragma once
#include <Eigen/Dense>
#include <complex>
#include <optional>

namespace hinf::certify {

// A mode counts as unseen when the PBH matrix [A − λI; X] has a singular value this small
// relative to max(1, ‖[A; X]‖).
inline constexpr double kPbhRelativeTolerance = 1e-10;

struct UnseenMode {
  std::complex<double> lambda;  // the eigenvalue of A
  Eigen::VectorXcd direction;   // v, ‖v‖ = 1: (A − λI) v ≈ 0 and X v ≈ 0
};

// The first eigenvalue λ of A (in the eigensolver's order) outside the stability region
// (|λ| ≥ 1 in discrete time, Re λ ≥ 0 in continuous time) at which [A − λI; X] loses rank,
// if any. A is n×n, X has n columns.
std::optional<UnseenMode> unseen_unstable_mode(const Eigen::MatrixXd& A, const Eigen::MatrixXd& X, bool discrete);

}  // namespace hinf::certify
