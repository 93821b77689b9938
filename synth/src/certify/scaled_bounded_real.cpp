#include "certify/scaled_bounded_real.hpp"

#include <cmath>

#include "hinf/synth/error_system.hpp"
#include "hinf/synth/hinf_norm.hpp"

namespace hinf::certify {

using Eigen::MatrixXd;

namespace {
// Relative accuracy of each H∞ norm; its certified upper value is what is tested.
constexpr double kNormTolerance = 1e-10;
// Golden-section search over log λ: bracket half-width and steps (0.618^70 · 2·35 ≈ 2e-13).
constexpr double kLogLambdaHalfWidth = 35.0;
constexpr int kGoldenSteps = 70;
constexpr double kInvPhi = 0.6180339887498949;
}  // namespace

ScaledBoundedReal::ScaledBoundedReal(const synth::Plant& plant, const synth::StateSpace& error_system)
    : plant_(plant), e_(error_system) {
  const int N = static_cast<int>(e_.A.rows());
  const int j = plant.uncertain() ? plant.j() : 0, k = plant.uncertain() ? plant.k() : 0;
  pq_ = static_cast<int>(e_.B.cols());
  B_ = MatrixXd::Zero(N, pq_ + j);
  C_ = MatrixXd::Zero(plant.l() + k, N);
  D_ = MatrixXd::Zero(plant.l() + k, pq_ + j);
  C_.topRows(plant.l()) = e_.C;
}

double ScaledBoundedReal::scaled_norm(double gamma, double lambda) {
  const int n = plant_.n();
  B_.leftCols(pq_) = e_.B / gamma;
  if (plant_.uncertain()) {
    const double r = std::sqrt(lambda);  // H̄/√λ and √λ Ē
    B_.block(0, pq_, n, plant_.j()) = plant_.H / r;
    C_.block(plant_.l(), 0, plant_.k(), n) = r * plant_.E;
  }
  ++evaluations_;
  return synth::discrete_hinf_norm(e_.A, B_, C_, D_, kNormTolerance).norm;
}

double ScaledBoundedReal::gamma_at_multiplier(double lambda, double gamma_lo, double gamma_hi, double rel_tol) {
  // Root of f(γ) = ‖G_λ‖∞(γ) − 1 (decreasing in γ) by regula falsi with the Illinois
  // modification — superlinear where bisection needs log₂ of the bracket ratio — on a
  // bracket [lo, hi] with f(lo) ≥ 0 > f(hi) kept throughout, so the returned hi is
  // certified. Trial points stay ≥ rel_tol/2 inside the bracket (so a trial next to
  // the root closes it), and a bisection is taken whenever three steps have not halved
  // the bracket (so it always shrinks).
  double lo = gamma_lo, hi = gamma_hi;
  double flo = scaled_norm(lo, lambda) - 1.0;
  if (flo < 0) return lo;
  double fhi = scaled_norm(hi, lambda) - 1.0;
  if (!(fhi < 0)) return hi;  // the caller's contract: gamma_hi passes
  int side = 0;
  double width_before[3] = {INFINITY, INFINITY, INFINITY};
  for (int it = 0; hi - lo > rel_tol * hi; ++it) {
    const double pad = 0.5 * rel_tol * hi;
    const bool slow = hi - lo > 0.5 * width_before[it % 3];
    width_before[it % 3] = hi - lo;
    double m = slow ? 0.5 * (lo + hi) : (lo * fhi - hi * flo) / (fhi - flo);
    if (!std::isfinite(m)) m = 0.5 * (lo + hi);
    m = std::min(std::max(m, lo + pad), hi - pad);
    const double fm = scaled_norm(m, lambda) - 1.0;
    if (fm < 0) {
      hi = m;
      fhi = fm;
      if (side == -1) flo *= 0.5;
      side = -1;
    } else {
      lo = m;
      flo = fm;
      if (side == 1) fhi *= 0.5;
      side = 1;
    }
  }
  return hi;
}

ScaledBoundedRealTest ScaledBoundedReal::test(double gamma, bool stop_when_feasible) {
  const int evaluations_before = evaluations_;
  ScaledBoundedRealTest out;
  if (!plant_.uncertain()) {
    out.scaled_norm = scaled_norm(gamma, 0.0);
    out.norm_evaluations = evaluations_ - evaluations_before;
    out.feasible = out.scaled_norm < 1.0;
    return out;
  }
  auto norm_at = [&](double d) { return scaled_norm(gamma, std::exp(d)); };
  // Centre of the bracket: λ balancing the uncertainty loop's two gains ‖H̄‖/√λ ~ √λ‖Ē‖/γ.
  const double hn = plant_.H.norm(), en = plant_.E.norm();
  const double d0 = (hn > 0 && en > 0) ? std::log(gamma * hn / en) : 0.0;
  double a = d0 - kLogLambdaHalfWidth, b = d0 + kLogLambdaHalfWidth;
  double x1 = b - kInvPhi * (b - a), x2 = a + kInvPhi * (b - a);
  double f1 = norm_at(x1), f2 = norm_at(x2);
  double best_d = f1 <= f2 ? x1 : x2, best_f = std::min(f1, f2);
  for (int it = 0; it < kGoldenSteps; ++it) {
    if (stop_when_feasible && best_f < 1.0) break;
    if (f1 <= f2) {  // the minimum of the unimodal function is in [a, x2]
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - kInvPhi * (b - a);
      f1 = norm_at(x1);
      if (f1 < best_f) best_f = f1, best_d = x1;
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + kInvPhi * (b - a);
      f2 = norm_at(x2);
      if (f2 < best_f) best_f = f2, best_d = x2;
    }
  }
  out.norm_evaluations = evaluations_ - evaluations_before;
  out.lambda = std::exp(best_d);
  out.scaled_norm = best_f;
  out.feasible = out.scaled_norm < 1.0;
  return out;
}

ScaledBoundedRealTest scaled_bounded_real(const synth::Plant& plant, const synth::Filter& filter, double gamma,
                                          bool stop_when_feasible) {
  return ScaledBoundedReal(plant, synth::error_system(plant, filter)).test(gamma, stop_when_feasible);
}

}  // namespace hinf::certify
