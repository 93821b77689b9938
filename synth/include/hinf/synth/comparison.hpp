// A filter beside the Kalman predictor of the same plant (`hinf-synth compare`,
// docs/maths.md §25): the price of robustness in one table and one plot.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

struct FilterFigures {
  double hinf_norm_nominal = 0;  // worst-case gain on the nominal plant (symplectic pencil)
  double hinf_peak_theta = 0;    // where, rad/sample
  double h2_norm_nominal = 0;    // RMS error under unit white (w, v) (docs/maths.md (132))
  double robust_bound = 0;       // analysis LMI (50) over the admissible F; NaN for a certain plant
  std::vector<double> sigma;     // σ_max of the nominal error system on Comparison::theta
};

struct Comparison {
  std::vector<double> theta;  // rad/sample
  FilterFigures filter;       // the given filter
  FilterFigures kalman;       // the Kalman one-step predictor, or the Kalman filter x̂(k|k) beside a
                              // filtered estimate (kalman_predictor, docs/maths.md (143))
};

// The most frequencies a comparison evaluates.
inline constexpr int kMaxComparisonPoints = 100000;

// `points` log-spaced frequencies (2 to kMaxComparisonPoints) with both filters' peak
// frequencies added; Error InvalidInput naming --points otherwise.
Comparison compare_with_kalman(const Plant& plant, const Filter& filter, const Settings& settings, int points,
                               const KalmanNoise& noise = {});

}  // namespace hinf::synth
