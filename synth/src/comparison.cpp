// A filter beside the Kalman predictor (docs/maths.md §25).
#include "hinf/synth/comparison.hpp"

#include <cmath>

#include "hinf/certify/error_system.hpp"
#include "hinf/certify/frequency_sweep.hpp"
#include "hinf/certify/h2_norm.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/stability.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/synth/validate_plant.hpp"

namespace hinf::synth {
namespace {

FilterFigures figures(const Plant& plant, const Filter& filter, const Settings& settings) {
  const StateSpace es = certify::error_system(plant, filter);
  if (!(certify::spectral_radius(es.A) < 1))
    throw Error(ErrorCode::CheckFailed, "compare: the filter's nominal error system is not Schur stable (spectral "
                                        "radius " + significant_text(certify::spectral_radius(es.A), 10) + ")");
  FilterFigures f;
  const certify::HinfNorm h = certify::discrete_hinf_norm(es, 1e-10);
  f.hinf_norm_nominal = h.norm;
  f.hinf_peak_theta = h.peak_frequency;
  f.h2_norm_nominal = certify::discrete_h2_norm(es);
  f.robust_bound = plant.uncertain() ? robust_bound(plant, filter, settings) : NAN;
  return f;
}

}  // namespace

Comparison compare_with_kalman(const Plant& plant, const Filter& filter, const Settings& settings, int points,
                               const KalmanNoise& noise) {
  validate_plant(plant);
  if (points < 2 || points > kMaxComparisonPoints)
    throw Error(ErrorCode::InvalidInput, "--points = " + std::to_string(points) + ": must be in [2, " +
                                             std::to_string(kMaxComparisonPoints) + "]", "points");
  Comparison c;
  c.filter = figures(plant, filter, settings);
  Settings same_estimate = settings;  // the Kalman filter that estimates what the filter does (§18.6)
  same_estimate.estimate = filter.filtered() ? Estimate::Filtered : Estimate::Predicted;
  const SynthesisResult k = kalman_predictor(plant, same_estimate, noise);
  c.kalman = figures(plant, k.filter, settings);
  c.theta = certify::frequency_grid(points, {c.filter.hinf_peak_theta, c.kalman.hinf_peak_theta});
  c.filter.sigma = certify::sigma_max_on_grid(certify::error_system(plant, filter), c.theta);
  c.kalman.sigma = certify::sigma_max_on_grid(certify::error_system(plant, k.filter), c.theta);
  return c;
}

}  // namespace hinf::synth
