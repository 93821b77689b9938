// Frequency response G(e^{jθ}) = C (e^{jθ} I − A)⁻¹ B + D of a discrete-time system,
// evaluated in O(n²·p) per frequency after one Hessenberg reduction A = Q H Qᵀ
// (Laub, "Efficient multivariable frequency response computations", IEEE TAC 26, 1981).
#pragma once
#include <Eigen/Dense>

namespace hinf::certify::detail {

inline constexpr double kPi = 3.14159265358979323846;  // θ = π is the Nyquist frequency

class FrequencyResponse {
 public:
  FrequencyResponse(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                    const Eigen::MatrixXd& C, const Eigen::MatrixXd& D);
  // G(e^{jθ}); infinite entries if e^{jθ} is (numerically) an eigenvalue of A.
  Eigen::MatrixXcd at(double theta) const;
  // σ_max(G(e^{jθ})).
  double sigma_max(double theta) const;

 private:
  Eigen::MatrixXcd H_;   // upper Hessenberg, Qᵀ A Q
  Eigen::MatrixXcd QtB_; // Qᵀ B
  Eigen::MatrixXcd CQ_;  // C Q
  Eigen::MatrixXcd D_;
};

}  // namespace hinf::certify::detail
