#include "damped_newton.hpp"

#include <chrono>
#include <cmath>
#include <limits>

namespace hinf::sdp {
namespace {
// λ² counts as progress when it falls below this fraction of the best so far; otherwise,
// after CenteringOptions::stall_iterations, the centring has stalled at round-off.
constexpr double kProgressFactor = 0.5;
// Damped region: for λ above this the step is damped (1/(1 + λ) is safe by
// self-concordance) and f_t must decrease; at or below it the full step is taken and only
// the domain is checked (f_t's decrease ~λ²/2 may be below its round-off).
constexpr double kDampedRegionLambda = 0.25;
// Armijo's fraction of the predicted decrease α·λ² that a backtracked step must achieve.
constexpr double kArmijoFraction = 0.25;
// Backtracking halves α, from the full step down to the damped step.
constexpr double kBacktrackFactor = 0.5;
}  // namespace

CenteringResult damped_newton_centre(LogDetBarrier& barrier, const Eigen::VectorXd& z0,
                                     const CenteringOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  CenteringResult r;
  r.z = z0;
  r.lambda2 = std::numeric_limits<double>::infinity();
  double f = 0;
  if (!barrier.value(r.z, f)) {
    r.status = "start outside the domain";
    return r;
  }
  double best = std::numeric_limits<double>::infinity();
  int best_iter = 0;
  Eigen::VectorXd dz, zn;
  for (int k = 0;; ++k) {
    double l2 = 0;
    if (!barrier.accurate_newton(r.z, dz, l2)) {
      r.status = "QR Newton step failed";
      return r;
    }
    r.lambda2 = l2;
    if (opt.on_newton_step) opt.on_newton_step(k, l2);
    if (l2 <= opt.lambda2_tol) {
      r.centred = true;
      r.status = "centred";
      return r;
    }
    if (l2 < kProgressFactor * best) {
      best = l2;
      best_iter = k;
    } else if (k - best_iter >= opt.stall_iterations) {
      // λ² has stopped falling: the QR step's own round-off floor
      r.stalled = r.centred = l2 <= opt.lambda2_accept;
      r.status = "stalled";
      return r;
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (k >= opt.max_iterations || elapsed > opt.max_seconds || (opt.interrupted && opt.interrupted())) {
      r.status = k >= opt.max_iterations ? "iteration limit" : elapsed > opt.max_seconds ? "time limit" : "interrupted";
      return r;
    }
    // Step: backtracking from the full Newton step (Armijo, slope −λ²) down to the damped
    // step 1/(1 + λ), which needs no test in the damped region beyond f_t's decrease
    // (≥ 0.027 for λ > 1/4, far above its round-off); a full step with λ ≤ 1/4 decreases
    // f_t by ~λ²/2, which may be below its round-off, so there only the domain is checked.
    const double lam = std::sqrt(l2);
    const double damped = 1.0 / (1.0 + lam);
    double fn = 0;
    bool taken = false;
    const bool damped_region = lam > kDampedRegionLambda;
    for (double alpha = 1.0; alpha > damped && damped_region; alpha *= kBacktrackFactor) {
      zn = r.z + alpha * dz;
      if (barrier.value(zn, fn) && fn <= f - kArmijoFraction * alpha * l2) {
        taken = true;
        break;
      }
    }
    if (!taken) {
      zn = r.z + (damped_region ? damped : 1.0) * dz;
      if (!barrier.value(zn, fn) || (damped_region && !(fn < f))) {
        r.status = "step rejected (round-off)";
        r.stalled = r.centred = l2 <= opt.lambda2_accept;
        return r;
      }
    }
    r.z = zn;
    f = fn;
    ++r.iterations;
  }
}

}  // namespace hinf::sdp
