// Sampling a continuous-time linear plant ẋ = A_c x + (inputs) with sample time T
// (docs/maths.md §19). Every method gives the discrete state matrix A and the matrix Γ that
// maps an input held over the sample into the state: B = Γ B_c, G = Γ G_c, H = Γ H_c.
//   Euler:          A = I + T A_c,                          Γ = T I
//   ZeroOrderHold:  exp(T [A_c, I; 0, 0]) = [A, Γ; 0, I],   Γ = ∫₀ᵀ e^{A_c s} ds
//   Tustin:         A = (I − T A_c/2)⁻¹ (I + T A_c/2),      Γ = T (I − T A_c/2)⁻¹
// (the trapezoidal rule for the state, the input held: x(k+1) = x + (T/2) A_c (x + x(k+1)) + T B u).
// And the sampled covariance of white noise of intensity B_c B_cᵀ (Van Loan 1978):
//   exp(T [−A_c, B_c B_cᵀ; 0, A_cᵀ]) = [·, M₁₂; 0, M₂₂],   Q = M₂₂ᵀ M₁₂ = ∫₀ᵀ e^{A_c s} B_c B_cᵀ e^{A_cᵀ s} ds.
// Needs Eigen only.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

namespace hinf::models {

enum class Discretisation { Euler, ZeroOrderHold, Tustin };

inline const char* to_string(Discretisation d) {
  return d == Discretisation::Euler ? "euler" : d == Discretisation::Tustin ? "tustin" : "zoh";
}

// The sizes of the block matrices below: 2N, or dynamic.
template <int N>
constexpr int kDoubled = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N;

// exp(T [A_c, I; 0, 0]) = [A, Γ; 0, I]: the zero-order-hold A and Γ = ∫₀ᵀ e^{A_c s} ds. Fixed
// sizes stay fixed (no heap allocation); MatrixXd works too.
template <int N>
void held_input_transition(const Eigen::Matrix<double, N, N>& A_c, double T, Eigen::Matrix<double, N, N>& A,
                           Eigen::Matrix<double, N, N>& Gamma) {
  const Eigen::Index n = A_c.rows();
  Eigen::Matrix<double, kDoubled<N>, kDoubled<N>> M =
      Eigen::Matrix<double, kDoubled<N>, kDoubled<N>>::Zero(2 * n, 2 * n);
  M.topLeftCorner(n, n) = T * A_c;
  M.topRightCorner(n, n).setIdentity();
  M.topRightCorner(n, n) *= T;
  const Eigen::Matrix<double, kDoubled<N>, kDoubled<N>> expM = M.exp();
  A = expM.topLeftCorner(n, n);
  Gamma = expM.topRightCorner(n, n);
}

// The zero-order hold is computed to working accuracy while T ‖A_c‖ stays below this: the
// exponential of [T A_c, T I; 0, 0] by scaling and squaring loses Γ's accuracy in proportion to
// the squarings (measured on a damped two-mass plant, Γ = −A_c⁻¹ in the limit: exact to 1e-16
// at T ‖A_c‖ = 2e8, wrong by 1e-6 at 2e10, 1e-4 at 2e12, 60 % at 2e16, and Γ = 0 from 2e18 —
// "the process noise is zero"). A sample time that long beside the plant's fastest mode is
// refused rather than sampled wrongly.
constexpr double kMaxHeldInputStiffness = 1e8;

// Why the zero-order hold of A_c at T would not be accurate (T ‖A_c‖ beyond
// kMaxHeldInputStiffness), or "" if it is.
inline std::string held_input_problem(const Eigen::MatrixXd& A_c, double T) {
  const double stiffness = T * A_c.norm();
  if (!(stiffness > kMaxHeldInputStiffness)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", stiffness);
  return "T ‖A‖ = " + std::string(text) + " is beyond 1e8, where the zero-order hold is no longer computed to "
         "working accuracy (docs/maths.md §19): sample faster, use discretisation: euler or tustin, or give the "
         "discrete plant";
}

struct SampledMatrices {
  Eigen::MatrixXd A;      // discrete state matrix
  Eigen::MatrixXd Gamma;  // held input → state
};

// A_c square, T > 0 and finite (the caller checks; non-finite results are the caller's to name).
inline SampledMatrices discretise(const Eigen::MatrixXd& A_c, double T, Discretisation d) {
  const Eigen::Index n = A_c.rows();
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  SampledMatrices out;
  if (d == Discretisation::Euler) {
    out.A = I + T * A_c;
    out.Gamma = T * I;
  } else if (d == Discretisation::Tustin) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(I - (T / 2) * A_c);
    out.A = lu.solve(I + (T / 2) * A_c);
    out.Gamma = lu.solve(T * I);
  } else {
    held_input_transition(A_c, T, out.A, out.Gamma);
  }
  return out;
}

// B with B Bᵀ = Q (Q symmetric positive semidefinite): V Λ^{1/2} from Q = V Λ Vᵀ, the
// columns of eigenvalues below the rounding level of Q (64 ε λ_max) dropped.
inline Eigen::MatrixXd covariance_factor(const Eigen::MatrixXd& Q) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Q);
  const Eigen::VectorXd& lambda = es.eigenvalues();
  const double floor =
      lambda.size() > 0 ? 64 * std::numeric_limits<double>::epsilon() * lambda.cwiseAbs().maxCoeff() : 0;
  Eigen::MatrixXd B(Q.rows(), 0);
  for (Eigen::Index i = lambda.size() - 1; i >= 0; --i) {
    if (!(lambda(i) > floor)) continue;
    B.conservativeResize(Eigen::NoChange, B.cols() + 1);
    B.col(B.cols() - 1) = es.eigenvectors().col(i) * std::sqrt(lambda(i));
  }
  return B;
}

// ∫₀ᵀ e^{A_c s} W e^{A_cᵀ s} ds for a white-noise intensity W (symmetric PSD) by Van Loan's
// block exponential, symmetrised. Fixed sizes stay fixed; MatrixXd works too.
template <int N>
Eigen::Matrix<double, N, N> sampled_white_noise_intensity(const Eigen::Matrix<double, N, N>& A_c,
                                                          const Eigen::Matrix<double, N, N>& W, double T) {
  const Eigen::Index n = A_c.rows();
  Eigen::Matrix<double, kDoubled<N>, kDoubled<N>> M =
      Eigen::Matrix<double, kDoubled<N>, kDoubled<N>>::Zero(2 * n, 2 * n);
  M.topLeftCorner(n, n) = -T * A_c;
  M.topRightCorner(n, n) = T * W;
  M.bottomRightCorner(n, n) = T * A_c.transpose();
  const Eigen::Matrix<double, kDoubled<N>, kDoubled<N>> expM = M.exp();
  const Eigen::Matrix<double, N, N> Q = expM.bottomRightCorner(n, n).transpose() * expM.topRightCorner(n, n);
  return 0.5 * (Q + Q.transpose());
}

// The same for the intensity B_c B_cᵀ.
inline Eigen::MatrixXd sampled_white_noise_covariance(const Eigen::MatrixXd& A_c, const Eigen::MatrixXd& B_c, double T) {
  return sampled_white_noise_intensity<Eigen::Dynamic>(A_c, B_c * B_c.transpose(), T);
}

}  // namespace hinf::models
