#include "hinf/certify/scaled_bounded_real.hpp"

#include <cmath>
#include <complex>

#include "frequency_response.hpp"
#include "golden_section.hpp"
#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"

namespace hinf::certify {

using Eigen::MatrixXd;

namespace {
// Relative accuracy of each H∞ norm; its certified upper value is what is tested.
constexpr double kNormTolerance = 1e-10;
// Golden-section search over log λ: bracket half-width and steps (0.618^70 · 2·35 ≈ 2e-13).
constexpr double kLogLambdaHalfWidth = 35.0;
constexpr int kScalingGoldenSteps = 70;
// Multiplier search by slopes: stop when the bracket in log λ is this narrow, or when
// the minimum of log‖G_λ‖∞ is known to kLogNormGap (the norms' own accuracy); at most
// kSlopeSearchMaxNorms norms before the golden-section fallback.
constexpr double kLogLambdaWidth = 1e-9;
constexpr double kLogNormGap = 1e-10;
constexpr int kSlopeSearchMaxNorms = 80;
// A best norm in [1, 1 + kFringe) is recomputed to kFineNormTolerance.
constexpr double kFringe = 1e-8;
constexpr double kFineNormTolerance = 1e-13;
// Block-diagonal F (docs/maths.md §23): each relative weight log w_b is searched by golden
// section over ±kLogWeightHalfWidth around its current value in kWeightGoldenSteps
// (0.618^40 · 2·20 ≈ 2e-7), in at most kMaxWeightSweeps sweeps over the blocks, stopping
// when a sweep lowers log‖G‖∞ by less than kLogNormGap.
constexpr double kLogWeightHalfWidth = 20.0;
constexpr int kWeightGoldenSteps = 40;
constexpr int kMaxWeightSweeps = 8;

// Regula falsi with the Illinois modification (superlinear where bisection is linear)
// for a root of f on [a, b] with f(a), f(b) of opposite signs (fa, fb given), until
// |b − a| ≤ width. The sides keep their signs, so a and b stay a bracket. Trial points
// stay ≥ pad inside it (a trial next to the root closes the bracket), and a bisection
// is taken whenever three steps have not halved it (so it always shrinks).
template <class F>
void illinois(F&& f, double& a, double& b, double fa, double fb, double width, double pad) {
  int side = 0;
  double width_before[3] = {INFINITY, INFINITY, INFINITY};
  for (int it = 0; std::abs(b - a) > width; ++it) {
    const bool slow = std::abs(b - a) > 0.5 * width_before[it % 3];
    width_before[it % 3] = std::abs(b - a);
    double m = slow ? 0.5 * (a + b) : (a * fb - b * fa) / (fb - fa);
    if (!std::isfinite(m)) m = 0.5 * (a + b);
    const double lo = std::min(a, b) + pad, hi = std::max(a, b) - pad;
    m = lo < hi ? std::min(std::max(m, lo), hi) : 0.5 * (a + b);
    const double fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
      if (side == 1) fb *= 0.5;
      side = 1;
    } else {
      b = m;
      fb = fm;
      if (side == -1) fa *= 0.5;
      side = -1;
    }
  }
}
}  // namespace

ScaledBoundedReal::ScaledBoundedReal(const hinf::Plant& plant, const hinf::StateSpace& error_system)
    : plant_(plant), e_(error_system) {
  const int N = static_cast<int>(e_.A.rows());
  const int j = plant.uncertain() ? plant.j() : 0, k = plant.uncertain() ? plant.k() : 0;
  pq_ = static_cast<int>(e_.B.cols());
  B_ = MatrixXd::Zero(N, pq_ + j);
  C_ = MatrixXd::Zero(plant.l() + k, N);
  D_ = MatrixXd::Zero(plant.l() + k, pq_ + j);
  C_.topRows(plant.l()) = e_.C;
  weights_ = Eigen::VectorXd::Ones(plant.structured() ? static_cast<Eigen::Index>(plant.F_blocks.size()) : 1);
}

hinf::certify::HinfNorm ScaledBoundedReal::scaled_hinf_norm(double gamma, double lambda, double norm_tolerance) {
  const int n = plant_.n();
  B_.leftCols(pq_) = e_.B / gamma;
  D_.topLeftCorner(plant_.l(), pq_) = e_.D / gamma;  // the filtered observer's feedthrough (141)
  if (plant_.uncertain() && !plant_.structured()) {
    const double r = std::sqrt(lambda);  // H̄/√λ and √λ Ē
    B_.block(0, pq_, n, plant_.j()) = plant_.H / r;
    C_.block(plant_.l(), 0, plant_.k(), n) = r * plant_.E;
  } else if (plant_.uncertain()) {
    Eigen::Index b = 0;
    for (const auto& [at, size] : plant_.F_block_ranges()) {
      const double r = std::sqrt(lambda * weights_(b++));  // block by block: H̄_b/√λ_b and √λ_b Ē_b
      B_.block(0, pq_ + at, n, size) = plant_.H.middleCols(at, size) / r;
      C_.block(plant_.l() + at, 0, size, n) = r * plant_.E.middleRows(at, size);
    }
  }
  ++evaluations_;
  return hinf::certify::discrete_hinf_norm(e_.A, B_, C_, D_, norm_tolerance);
}

double ScaledBoundedReal::scaled_norm(double gamma, double lambda) {
  return scaled_hinf_norm(gamma, lambda, kNormTolerance).norm;
}

double ScaledBoundedReal::gamma_at_multiplier(double lambda, double gamma_lo, double gamma_hi, double rel_tol) {
  // Root of f(γ) = ‖G_λ‖∞(γ) − 1, decreasing in γ, on the bracket [lo, hi] with
  // f(lo) ≥ 0 > f(hi) kept throughout (Illinois), so the returned hi is certified.
  double lo = gamma_lo, hi = gamma_hi;
  const double flo = scaled_norm(lo, lambda) - 1.0;
  if (flo < 0) return lo;
  const double fhi = scaled_norm(hi, lambda) - 1.0;
  if (!(fhi < 0)) return hi;  // the caller's contract: gamma_hi passes
  illinois([&](double g) { return scaled_norm(g, lambda) - 1.0; }, lo, hi, flo, fhi, rel_tol * gamma_hi,
           0.5 * rel_tol * gamma_lo);
  return hi;
}

ScaledBoundedReal::Slope ScaledBoundedReal::scaled_norm_and_slope(double gamma, double log_lambda) {
  Slope out;
  const hinf::certify::HinfNorm h = scaled_hinf_norm(gamma, std::exp(log_lambda), kNormTolerance);
  out.norm = h.norm;
  // d‖G_λ‖∞/d log λ at the peak: G_λ = [G₁₁, G₁₂/√λ; √λ G₂₁, G₂₂] in the blocks (l, k) ×
  // (p + q, j), so ∂G/∂ log λ = ½[0, −G₁₂; G₂₁, 0] and, with u, v the top singular
  // vectors there, ∂σ_max = Re(uᴴ ∂G v) (a subgradient where the peak is not unique).
  const Eigen::MatrixXcd G = hinf::certify::detail::FrequencyResponse(e_.A, B_, C_, D_).at(h.peak_frequency);
  if (!G.allFinite()) return out;
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(G, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXcd u = svd.matrixU().col(0), v = svd.matrixV().col(0);
  const int l = plant_.l(), k = plant_.k(), j = plant_.j();
  const std::complex<double> d =
      0.5 * (u.tail(k).dot(G.bottomLeftCorner(k, pq_) * v.head(pq_)) -
             u.head(l).dot(G.topRightCorner(l, j) * v.tail(j)));
  out.slope = svd.singularValues()(0) > 0 ? d.real() / svd.singularValues()(0) : 0.0;
  out.slope_ok = std::isfinite(out.slope);
  return out;
}

// log‖G_λ‖∞ is convex in d = log λ, with slopes from the top singular vectors at the peak
// frequency. The minimiser stays bracketed by [d_l, d_r] with slope(d_l) < 0 < slope(d_r);
// the tangents there bound the minimum from below where they meet (convexity). Trial
// points alternate between that meeting point (exact at a kink, where two peak
// frequencies trade places — the paper's case) and the secant zero of the slope
// (superlinear where the minimum is smooth), with a bisection whenever three trials have
// not halved the bracket. Stops when the best value is within kLogNormGap of the bound,
// or when the bound is ≥ 0 and only the verdict was asked for (then min ‖G_λ‖∞ ≥ 1 up to
// the norms' accuracy).
bool ScaledBoundedReal::slope_search(double gamma, double d0, Best& best) {
  const double a = d0 - kLogLambdaHalfWidth, b = d0 + kLogLambdaHalfWidth;
  const Slope sa = scaled_norm_and_slope(gamma, a);
  best.record(a, sa.norm);
  const Slope sb = best.done() ? Slope{} : scaled_norm_and_slope(gamma, b);
  best.record(b, sb.norm);
  if (best.done() || !sa.slope_ok || !sb.slope_ok || !(sa.slope < 0) || !(sb.slope > 0)) return false;
  double dl = a, fl = std::log(sa.norm), sl = sa.slope;
  double dr = b, fr = std::log(sb.norm), sr = sb.slope;
  double width_before[3] = {INFINITY, INFINITY, INFINITY};
  for (int it = 0; it < kSlopeSearchMaxNorms && !best.done(); ++it) {
    const double meet = (fr - fl + sl * dl - sr * dr) / (sl - sr);
    const double bound = fl + sl * (meet - dl);
    if (dr - dl <= kLogLambdaWidth || std::log(best.f) - bound <= kLogNormGap ||
        (best.stop_when_feasible && bound >= 0))
      return true;
    const bool slow = dr - dl > 0.5 * width_before[it % 3];
    width_before[it % 3] = dr - dl;
    const double secant = (dl * sr - dr * sl) / (sr - sl);
    double m = slow ? 0.5 * (dl + dr) : (it % 2 == 0 ? meet : secant);
    const double pad = 0.25 * kLogLambdaWidth;
    if (!std::isfinite(m)) m = 0.5 * (dl + dr);
    m = std::min(std::max(m, dl + pad), dr - pad);
    const Slope p = scaled_norm_and_slope(gamma, m);
    best.record(m, p.norm);
    if (!p.slope_ok) return false;
    if (p.slope < 0) {
      dl = m, fl = std::log(p.norm), sl = p.slope;
    } else {
      dr = m, fr = std::log(p.norm), sr = p.slope;
    }
  }
  return false;
}

// Golden-section search over the whole bracket, which needs only the norm's unimodality.
void ScaledBoundedReal::golden_section_search(double gamma, double d0, Best& best) {
  auto norm_at = [&](double d) {
    const double f = scaled_norm(gamma, std::exp(d));
    best.record(d, f);
    return f;
  };
  detail::golden_section_minimise(norm_at, d0 - kLogLambdaHalfWidth, d0 + kLogLambdaHalfWidth,
                                  kScalingGoldenSteps, [&best](double, double) { return best.done(); });
}

void ScaledBoundedReal::search_common_multiplier(double gamma, double d0, Best& best) {
  // 1. the slope search; 2. if it was not possible (a slope missing or of the wrong sign
  // at the bracket's ends) or did not converge (the norm budget spent), golden section.
  const bool located = slope_search(gamma, d0, best);
  if (!(best.f < 1.0) && !located) golden_section_search(gamma, d0, best);
}

// ‖D G D⁻¹‖∞ is convex in the log-scalings (Sezginer & Overton 1990, the maximum over θ of
// convex functions), so φ(log w_b) = min over λ of it, the others fixed, is convex too
// (partial minimisation): each golden-section step minimises over λ inside. With two
// blocks this is the joint minimum; with more, a cyclic search may stop short of it at a
// kink, which can only make the check conservative, never wrong (every norm is certified).
void ScaledBoundedReal::search_block_weights(double gamma, Best& best) {
  for (int sweep = 0; sweep < kMaxWeightSweeps && !best.done(); ++sweep) {
    const double before = best.f;
    for (Eigen::Index b = 1; b < weights_.size() && !best.done(); ++b) {
      const double w0 = std::log(weights_(b));
      double best_w = w0;
      auto phi = [&](double lw) {
        weights_(b) = std::exp(lw);
        Best inner;  // the minimum over λ, not only the verdict (its tangent bound ≥ 0 is not enough here)
        inner.stop_when_feasible = false;
        search_common_multiplier(gamma, best.d, inner);
        if (inner.f < best.f) best.f = inner.f, best.d = inner.d, best_w = lw;
        return inner.f;
      };
      detail::golden_section_minimise(phi, w0 - kLogWeightHalfWidth, w0 + kLogWeightHalfWidth, kWeightGoldenSteps,
                                      [&best](double, double) { return best.done(); });
      weights_(b) = std::exp(best_w);
    }
    if (!(std::log(before) - std::log(best.f) > kLogNormGap)) break;
  }
}

ScaledBoundedRealTest ScaledBoundedReal::test(double gamma, bool stop_when_feasible, const Eigen::VectorXd& start) {
  const int evaluations_before = evaluations_;
  ScaledBoundedRealTest out;
  if (!plant_.uncertain()) {
    out.scaled_norm = scaled_norm(gamma, 0.0);
    out.norm_evaluations = evaluations_ - evaluations_before;
    out.feasible = out.scaled_norm < 1.0;
    return out;
  }
  Best best;
  best.stop_when_feasible = stop_when_feasible;
  // Bracket centred at the λ balancing the uncertainty loop's two gains ‖H̄‖/√λ ~ √λ‖Ē‖/γ.
  const double hn = plant_.H.norm(), en = plant_.E.norm();
  const double d0 = (hn > 0 && en > 0) ? std::log(gamma * hn / en) : 0.0;
  weights_.setOnes();
  if (plant_.structured() && start.size() == weights_.size() && (start.array() > 0).all() && start.allFinite())
    weights_ = start / start(0);
  if (!plant_.structured()) {
    search_common_multiplier(gamma, d0, best);
  } else {
    Best common;  // located, not just decided: the weights' search starts from its λ
    common.stop_when_feasible = false;
    search_common_multiplier(gamma, d0, common);
    best.record(common.d, common.f);
    if (!best.done()) search_block_weights(gamma, best);
  }
  // 3. Within the norms' accuracy of 1 the verdict depends on their rounding: decide it
  //    with one norm to 1e-13 at the best multiplier.
  if (!(best.f < 1.0) && best.f < 1.0 + kFringe) {
    const double f = scaled_hinf_norm(gamma, std::exp(best.d), kFineNormTolerance).norm;
    if (f < best.f) best.f = f;
  }
  out.norm_evaluations = evaluations_ - evaluations_before;
  out.lambda = std::exp(best.d);
  out.multipliers = out.lambda * weights_;
  out.scaled_norm = best.f;
  out.feasible = best.f < 1.0;
  return out;
}

ScaledBoundedRealTest scaled_bounded_real(const hinf::Plant& plant, const hinf::Filter& filter, double gamma,
                                          bool stop_when_feasible) {
  return ScaledBoundedReal(plant, hinf::certify::error_system(plant, filter)).test(gamma, stop_when_feasible);
}

}  // namespace hinf::certify
