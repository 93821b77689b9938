// estimated_peak_bytes (memory_model.hpp).
#include "hinf/sdp/memory_model.hpp"

namespace hinf::sdp {

double estimated_peak_bytes(long order, long params) {
  const double N = static_cast<double>(order), p = static_cast<double>(params);
  const double svec_rows = N * (N + 1) / 2;
  const double doubles = kHessianDoublesPerParamSquared * p * p + kJacobianCopies * svec_rows * p;
  return kBaseBytes + 8.0 * doubles;
}

}  // namespace hinf::sdp
