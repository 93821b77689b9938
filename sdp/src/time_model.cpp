// estimated_solve_time (time_model.hpp).
#include "hinf/sdp/time_model.hpp"

namespace hinf::sdp {

TimeEstimate estimated_solve_time(double hessian_multiply_adds, long params) {
  const double p = static_cast<double>(params);
  TimeEstimate e;
  e.newton_iteration_s = kSecondsPerHessianMultiplyAdd * hessian_multiply_adds +
                         kSecondsPerFactorMultiplyAdd * 2.0 * p * p * p / 3.0 + kSecondsPerNewtonEntry * p * p;
  e.fewest_s = kFewestNewtonIterations * e.newton_iteration_s;
  e.most_s = kMostNewtonIterations * e.newton_iteration_s;
  return e;
}

}  // namespace hinf::sdp
