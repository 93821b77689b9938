// Bisection of a bracket [good, bad] (internal to hinf_synth; docs/maths.md §21): the one
// loop of sweep's searches, which stops at the tolerance asked for or at floating-point
// resolution, whichever comes first (a tolerance below the spacing of doubles near the
// bracket would otherwise never be reached).
#pragma once
#include <cmath>

namespace hinf::synth {

// While bad − good > tolerance (either order: good may lie above bad) and the midpoint is a
// double strictly between them, evaluates still_good(mid) and moves good or bad to it.
// Returns the number of evaluations.
template <class StillGood>
int bisect(double& good, double& bad, double tolerance, const StillGood& still_good) {
  int evaluations = 0;
  while (std::fabs(bad - good) > tolerance) {
    const double mid = 0.5 * (good + bad);
    if (!(mid > std::fmin(good, bad) && mid < std::fmax(good, bad))) break;  // no double in between
    ++evaluations;
    if (still_good(mid)) good = mid;
    else bad = mid;
  }
  return evaluations;
}

}  // namespace hinf::synth
