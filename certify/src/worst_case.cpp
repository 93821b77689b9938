// The worst constant admissible F for a fixed filter, by sampling and a local search
// (docs/maths.md §24).
#include "hinf/certify/worst_case.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "admissible_f.hpp"
#include "gaussian_source.hpp"
#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/stability.hpp"

namespace hinf::certify {
namespace {

// Accuracy of each norm (its lower value σ_max(peak) is what is reported).
constexpr double kWorstCaseNormTolerance = 1e-8;
// Local search: trials from the worst sample, a perturbation of relative size `step` (first
// kInitialStep), halved after kMissesPerHalving trials without gain, at most kTrials.
constexpr double kInitialStep = 0.5;
constexpr int kMissesPerHalving = 8;
constexpr int kTrials = 200;
// Compass search over a box: first step a quarter of each scalar's width, stopped below
// kSmallestBoxStep of it or after kBoxTrials norms of its own.
constexpr double kFirstBoxStep = 0.25;
constexpr double kSmallestBoxStep = 1e-4;
constexpr int kBoxTrials = 400;

// σ_max at the peak of the error system at F; +inf if it is not Schur stable.
double gain_at(const Plant& plant, const Filter& filter, const Eigen::MatrixXd& F, int& evaluations) {
  const StateSpace es = error_system(plant, filter, F);
  if (!(spectral_radius(es.A) < 1)) return INFINITY;
  ++evaluations;
  return discrete_hinf_norm(es, kWorstCaseNormTolerance).lower_bound;
}

// The radical inverse of i in base b (the Halton sequence's coordinate b), in [0, 1).
double radical_inverse(unsigned long i, unsigned b) {
  double x = 0, f = 1.0 / b;
  for (; i > 0; i /= b, f /= b) x += f * static_cast<double>(i % b);
  return x;
}

Eigen::MatrixXd diagonal_of_scalars(const std::vector<int>& sizes, const Eigen::VectorXd& delta) {
  Eigen::Index j = 0;
  for (int s : sizes) j += s;
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(j, j);
  Eigen::Index at = 0;
  for (std::size_t b = 0; b < sizes.size(); ++b) {
    F.block(at, at, sizes[b], sizes[b]).diagonal().setConstant(delta(static_cast<Eigen::Index>(b)));
    at += sizes[b];
  }
  return F;
}

}  // namespace

WorstCaseOverBox worst_case_gain_over_box(const Plant& plant, const Filter& filter, const std::vector<int>& sizes,
                                          const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, int samples) {
  static constexpr unsigned kPrimes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53};
  const Eigen::Index K = lower.size();
  WorstCaseOverBox out;
  out.gain = -1;
  out.delta = Eigen::VectorXd::Zero(K);
  const auto try_at = [&](const Eigen::VectorXd& delta) {  // true if δ is the new worst
    const double g = gain_at(plant, filter, diagonal_of_scalars(sizes, delta), out.evaluations);
    if (!(g > out.gain)) return false;
    out.gain = g, out.delta = delta;
    return true;
  };
  const Eigen::VectorXd width = upper - lower;
  std::vector<Eigen::VectorXd> candidates{Eigen::VectorXd::Zero(K).cwiseMax(lower).cwiseMin(upper)};
  if (K <= kMaxBoxVertexDimension)
    for (unsigned long v = 0; v < (1ul << K); ++v) {
      Eigen::VectorXd d(K);
      for (Eigen::Index b = 0; b < K; ++b) d(b) = (v >> b) & 1ul ? upper(b) : lower(b);
      candidates.push_back(d);
    }
  for (int i = 1; i <= samples && K <= static_cast<Eigen::Index>(std::size(kPrimes)); ++i) {
    Eigen::VectorXd d(K);
    for (Eigen::Index b = 0; b < K; ++b) d(b) = lower(b) + width(b) * radical_inverse(static_cast<unsigned long>(i), kPrimes[b]);
    candidates.push_back(d);
  }
  for (const Eigen::VectorXd& d : candidates)
    if (try_at(d) && std::isinf(out.gain)) return out;
  const int budget = out.evaluations + kBoxTrials;
  for (double step = kFirstBoxStep; step >= kSmallestBoxStep && out.evaluations < budget;) {
    bool gained = false;
    for (Eigen::Index b = 0; b < K && !gained; ++b)
      for (double sign : {1.0, -1.0}) {
        Eigen::VectorXd d = out.delta;
        d(b) = std::clamp(d(b) + sign * step * width(b), lower(b), upper(b));
        if (d(b) == out.delta(b)) continue;
        if (try_at(d)) {
          if (std::isinf(out.gain)) return out;
          gained = true;
          break;
        }
      }
    if (!gained) step /= 2;
  }
  return out;
}

WorstCaseGain worst_case_gain(const Plant& plant, const Filter& filter, int random_samples, unsigned seed) {
  WorstCaseGain out;
  out.gain = -1;
  for (const Eigen::MatrixXd& F : admissible_samples(plant, random_samples, seed)) {
    const double g = gain_at(plant, filter, F, out.evaluations);
    if (g > out.gain) out.gain = g, out.worst_F = F;
    if (std::isinf(g)) return out;
  }
  if (!plant.uncertain()) return out;
  if (out.worst_F.size() == 0) out.worst_F = Eigen::MatrixXd::Zero(plant.j(), plant.k());
  detail::GaussianSource normal(seed + 1);
  double step = kInitialStep;
  int misses = 0;
  for (int t = 0; t < kTrials && step > 1e-6; ++t) {
    Eigen::MatrixXd D(out.worst_F.rows(), out.worst_F.cols());
    for (Eigen::Index i = 0; i < D.size(); ++i) D(i) = normal.next();
    const Eigen::MatrixXd F = detail::onto_blocks(plant, out.worst_F + step * D / D.norm(), detail::BlockNorm::AtMostOne);
    const double g = gain_at(plant, filter, F, out.evaluations);
    if (g > out.gain) {
      out.gain = g, out.worst_F = F, misses = 0;
      if (std::isinf(g)) return out;
    } else if (++misses == kMissesPerHalving) {
      step /= 2, misses = 0;
    }
  }
  return out;
}

}  // namespace hinf::certify
