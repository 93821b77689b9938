// H2 norm by the Gramian (docs/maths.md (132)); see h2_norm.hpp.
#include "hinf/certify/h2_norm.hpp"

#include <cmath>

#include "hinf/certify/stability.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"

namespace hinf::certify {
namespace {
// Stop once ‖A^(2^k)‖_F is below this: the terms left, A^(2^k) P A^(2^k)ᵀ, are at most
// its square (1e-18) times ‖P‖.
constexpr double kDoublingTolerance = 1e-9;
constexpr int kMaxSquarings = 64;
}  // namespace

double discrete_h2_norm(const StateSpace& s) {
  const double rho = spectral_radius(s.A);
  if (!(rho < 1.0))
    throw Error(ErrorCode::Infeasible, "H2 norm: A is not Schur stable (spectral radius " + number_text(rho) + ")");
  Eigen::MatrixXd P = s.B * s.B.transpose(), Ak = s.A;
  for (int k = 0;; ++k) {
    if (k == kMaxSquarings)
      throw Error(ErrorCode::NumericalFailure, "H2 norm: Smith's doubling did not converge (spectral radius " +
                                                   number_text(rho) + ")");
    P += Ak * P * Ak.transpose();
    Ak = Ak * Ak;
    if (!Ak.allFinite() || !P.allFinite())
      throw Error(ErrorCode::NumericalFailure, "H2 norm: the Gramian overflowed");
    if (Ak.norm() <= kDoublingTolerance) break;
  }
  const double sq = (s.C * P * s.C.transpose()).trace() + (s.D.size() > 0 ? s.D.squaredNorm() : 0.0);
  return std::sqrt(std::max(0.0, sq));
}

}  // namespace hinf::certify
