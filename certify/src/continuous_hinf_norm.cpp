// continuous_hinf_norm (hinf_norm.hpp): the bilinear map onto discrete_hinf_norm.
#include <cmath>
#include <sstream>

#include "hinf/certify/balance.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/common/error.hpp"

namespace hinf::certify {

namespace {

// The bilinear map's frequency scale: the geometric mean of the extreme pole moduli, so
// that both ends of the spectrum land away from z = ±1.
double bilinear_scale(const Eigen::VectorXcd& poles) {
  double lo = INFINITY, hi = 0;
  for (Eigen::Index i = 0; i < poles.size(); ++i) {
    const double r = std::abs(poles(i));
    if (r > 0) lo = std::min(lo, r), hi = std::max(hi, r);
  }
  return hi > 0 ? std::sqrt(lo * hi) : 1.0;
}

}  // namespace

HinfNorm continuous_hinf_norm(const StateSpace& G, double rel_tol) {
  const Eigen::Index n = G.A.rows();
  if (n == 0) return discrete_hinf_norm(G, rel_tol);
  const Eigen::VectorXcd poles = balanced_eigenvalues(G.A);
  const double abscissa = poles.real().maxCoeff();
  if (!(abscissa < 0)) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "continuous_hinf_norm: A is not Hurwitz (spectral abscissa " << abscissa << " >= 0); the H∞ norm is infinite";
    throw Error(ErrorCode::Infeasible, msg.str());
  }
  const double alpha = bilinear_scale(poles);
  const Eigen::MatrixXd shifted = alpha * Eigen::MatrixXd::Identity(n, n) - G.A;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(shifted);
  const Eigen::MatrixXd resolvent_B = lu.solve(G.B);
  // C (αI − A)⁻¹ = ((αI − A)⁻ᵀ Cᵀ)ᵀ
  const Eigen::MatrixXd C_resolvent =
      Eigen::PartialPivLU<Eigen::MatrixXd>(shifted.transpose()).solve(G.C.transpose()).transpose();
  StateSpace d;
  d.A = lu.solve(alpha * Eigen::MatrixXd::Identity(n, n) + G.A);
  d.B = std::sqrt(2 * alpha) * resolvent_B;
  d.C = std::sqrt(2 * alpha) * C_resolvent;
  d.D = G.D + G.C * resolvent_B;
  HinfNorm h;
  try {
    h = discrete_hinf_norm(d, rel_tol);
  } catch (const Error& e) {
    // the poles were Hurwitz above: a bilinear image on or outside the unit circle is rounding
    // (poles spread over too many decades for one α), a numerical failure, not an infinite norm
    if (e.code() != ErrorCode::Infeasible) throw;
    std::ostringstream msg;
    msg.precision(17);
    msg << "continuous-time H∞ norm: the poles are stable (spectral abscissa " << abscissa
        << " < 0) but their bilinear images (α = " << alpha
        << ") reach the unit circle in rounding: the poles span too many decades to be computed with";
    throw Error(ErrorCode::NumericalFailure, msg.str());
  }
  h.peak_frequency = alpha * std::tan(h.peak_frequency / 2);
  return h;
}

}  // namespace hinf::certify
