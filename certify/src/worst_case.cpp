// The worst constant admissible F for a fixed filter, by sampling and a local search
// (docs/maths.md §24).
#include "hinf/certify/worst_case.hpp"

#include <cmath>

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

// σ_max at the peak of the error system at F; +inf if it is not Schur stable.
double gain_at(const Plant& plant, const Filter& filter, const Eigen::MatrixXd& F, int& evaluations) {
  const StateSpace es = error_system(plant, filter, F);
  if (!(spectral_radius(es.A) < 1)) return INFINITY;
  ++evaluations;
  return discrete_hinf_norm(es, kWorstCaseNormTolerance).lower_bound;
}

}  // namespace

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
