// The witness of docs/maths.md §3.7, eq. (119); see quadratic_stability.hpp.
#include "hinf/certify/quadratic_stability.hpp"

#include <cmath>
#include <complex>
#include <limits>

#include "hinf/certify/hinf_norm.hpp"

namespace hinf::certify {
namespace {

using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using Eigen::VectorXcd;
using cld = std::complex<long double>;

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;
constexpr long double kLongUnitRoundoff = std::numeric_limits<long double>::epsilon() / 2;
// The H∞ norm only locates the peak; its accuracy does not enter the bound.
constexpr double kPeakRelTol = 1e-8;
// |fl(cos θ)|² + |fl(sin θ)|² is within a few units of roundoff of 1 (libm's error is
// below one ulp); scaling both by 1 + kModulusLift puts z outside the unit circle.
constexpr double kModulusLift = 16 * kUnitRoundoff;

// γ_k of a k-term sum of complex products in long double (Higham §3.6: √2·γ₂ per product).
long double gamma_complex(int k) {
  const long double g = (k + 2) * kLongUnitRoundoff;
  return 1.5L * g / (1 - g);
}

// (K v)ᵢ = z vᵢ − Σₖ Aᵢₖ vₖ for the exact K = zI − A (not its rounded form), in long double;
// `mag` receives the sum of the magnitudes of the terms, for the rounding bound.
cld exact_k_times(const MatrixXd& A, std::complex<double> z, const Eigen::Ref<const VectorXcd>& v, int i,
                  long double& mag) {
  const cld zi = cld(z.real(), z.imag()) * cld(v(i).real(), v(i).imag());
  cld s = zi;
  mag = std::abs(zi);
  for (int k = 0; k < A.cols(); ++k) {
    const cld t = static_cast<long double>(A(i, k)) * cld(v(k).real(), v(k).imag());
    s -= t;
    mag += std::abs(t);
  }
  return s;
}

// r = b − K x with K = zI − A exact, and a bound on its rounding, in long double.
struct Residual {
  long double norm = 0;      // ‖r̂‖₂
  long double error = 0;     // ‖r − r̂‖₂ ≤ error
};

Residual residual(const MatrixXd& A, std::complex<double> z, const VectorXcd& x, const VectorXcd& b) {
  Residual out;
  const int n = static_cast<int>(A.rows());
  long double sq = 0, err = 0;
  for (int i = 0; i < n; ++i) {
    long double mag = 0;
    const cld s = cld(b(i).real(), b(i).imag()) - exact_k_times(A, z, x, i, mag);
    sq += std::norm(s);
    const long double e = gamma_complex(n + 2) * (mag + std::abs(cld(b(i).real(), b(i).imag())));
    err += e * e;
  }
  out.norm = std::sqrt(sq);
  out.error = std::sqrt(err);
  return out;
}

// ‖M‖_F in long double, rounded up.
long double frobenius_up(const MatrixXcd& M) {
  long double s = 0;
  for (int j = 0; j < M.cols(); ++j)
    for (int i = 0; i < M.rows(); ++i) s += std::norm(cld(M(i, j).real(), M(i, j).imag()));
  return std::sqrt(s) * (1 + 4 * kLongUnitRoundoff * (M.size() + 2));
}

// ‖K⁻¹‖₂ ≤ ‖X‖_F / (1 − ‖I − K X‖_F) for K = zI − A and an approximate inverse X (Neumann
// series), the product's rounding included; +∞ if ‖I − K X‖_F is not verified below 1.
long double inverse_norm_bound(const MatrixXd& A, std::complex<double> z, const MatrixXcd& X) {
  const int n = static_cast<int>(A.rows());
  long double sq = 0, err = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      long double mag = 0;
      const cld s = (i == j ? cld(1) : cld(0)) - exact_k_times(A, z, X.col(j), i, mag);
      sq += std::norm(s);
      const long double e = gamma_complex(n + 2) * (mag + (i == j ? 1 : 0));
      err += e * e;
    }
  const long double rho = (std::sqrt(sq) + std::sqrt(err)) * (1 + 8 * kLongUnitRoundoff);
  if (!(rho < 1)) return std::numeric_limits<long double>::infinity();
  return frobenius_up(X) / (1 - rho);
}

}  // namespace

GainWitness uncertainty_gain_witness(const MatrixXd& A, const MatrixXd& H, const MatrixXd& E) {
  GainWitness w;
  const int n = static_cast<int>(A.rows());
  if (H.cols() == 0 || E.rows() == 0 || H.isZero(0.0) || E.isZero(0.0)) return w;
  const HinfNorm peak = discrete_hinf_norm(A, H, E, MatrixXd::Zero(E.rows(), H.cols()), kPeakRelTol);
  w.gain = peak.norm;
  w.theta = peak.peak_frequency;
  if (!(peak.lower_bound > 1)) return w;
  // z with |z| ≥ 1 exactly and the right singular vector u of the computed G(z); K̂ is the
  // rounded zI − A, used only to compute x̂ and X — the bounds below use the exact K
  const std::complex<double> z((1 + kModulusLift) * std::cos(w.theta), (1 + kModulusLift) * std::sin(w.theta));
  MatrixXcd K = -A.cast<std::complex<double>>();
  K.diagonal().array() += z;
  const Eigen::PartialPivLU<MatrixXcd> lu(K);
  const MatrixXcd Hc = H.cast<std::complex<double>>(), Ec = E.cast<std::complex<double>>();
  const MatrixXcd G = Ec * lu.solve(Hc);
  const VectorXcd u = Eigen::JacobiSVD<MatrixXcd>(G, Eigen::ComputeThinV).matrixV().col(0);
  // x̂ ≈ K⁻¹ H u; the exact x = K⁻¹ H u = x̂ + K⁻¹ (H u − K x̂)
  const VectorXcd b = Hc * u;
  const VectorXcd x = lu.solve(b);
  // b̂ = fl(H u): the residual is taken against H u itself, fl's rounding added
  Residual r = residual(A, z, x, b);
  long double hu_err = 0;
  for (int i = 0; i < n; ++i) {
    long double mag = 0;
    for (int k = 0; k < H.cols(); ++k) mag += std::abs(H(i, k)) * std::abs(cld(u(k).real(), u(k).imag()));
    const double k = static_cast<double>(H.cols()) + 2;  // double γ_k of H·u (real × complex)
    const long double e = 1.5L * k * kUnitRoundoff / (1 - k * kUnitRoundoff) * mag;
    hu_err += e * e;
  }
  r.error += std::sqrt(hu_err);
  const long double kinv = inverse_norm_bound(A, z, lu.inverse());
  // ‖E x‖ ≥ ‖E x̂‖ − ‖E‖_F·‖K⁻¹‖·‖r‖, ‖E x̂‖ with its rounding
  long double ex_sq = 0, ex_err = 0;
  for (int i = 0; i < E.rows(); ++i) {
    cld s = 0;
    long double mag = 0;
    for (int k = 0; k < n; ++k) {
      const cld t = static_cast<long double>(E(i, k)) * cld(x(k).real(), x(k).imag());
      s += t;
      mag += std::abs(t);
    }
    ex_sq += std::norm(s);
    const long double e = gamma_complex(n) * mag;
    ex_err += e * e;
  }
  const long double e_norm = frobenius_up(Ec);
  long double u_sq = 0;
  for (int k = 0; k < u.size(); ++k) u_sq += std::norm(cld(u(k).real(), u(k).imag()));
  const long double u_norm = std::sqrt(u_sq) * (1 + 8 * kLongUnitRoundoff * (u.size() + 2));
  const long double lower = std::sqrt(ex_sq) * (1 - 8 * kLongUnitRoundoff * (E.rows() + 2)) - std::sqrt(ex_err) -
                            e_norm * kinv * (r.norm + r.error);
  // the final division and conversion, rounded down
  w.gain_lower_bound = static_cast<double>(lower / u_norm) * (1 - 4 * kUnitRoundoff);
  w.verified = std::isfinite(w.gain_lower_bound) && w.gain_lower_bound > 1;
  return w;
}

}  // namespace hinf::certify
