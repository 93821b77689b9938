// Accuracy metrics of one filter in one run, from its error series.
#pragma once
#include <optional>
#include <vector>

namespace hinf::sim {

struct MetricSettings {
  double steady_state_start_s = 0.0;  // window [start, end] for the RMS/max metrics
  double converge_threshold_m = 1.0;  // position-error threshold for converge_time_s
  // converge_time_s tests the RMS of |e_p| over the trailing window (t_k − W, t_k]; 0 (the
  // default) tests |e_p(k)| itself. A window makes the metric robust to isolated
  // measurement outliers, which any linear filter passes on in part.
  double converge_window_s = 0.0;
};

struct FilterMetrics {
  bool diverged = false;              // estimate non-finite or beyond the divergence limit
  std::optional<double> diverged_at_s;
  std::optional<double> position_rms_m;    // sqrt(mean |e_p|²) over the window
  std::optional<double> velocity_rms_mps;  // sqrt(mean |e_v|²) over the window
  std::optional<double> position_max_m;    // max |e_p| over the window
  // First t_k such that e(j) < threshold for every j ≥ k, e the trailing-window RMS of
  // |e_p| (MetricSettings::converge_window_s; |e_p| itself for a zero window); empty if
  // the last sample is not below the threshold (never converged).
  std::optional<double> converge_time_s;
  // The same with e = |e_p| whatever the window (equal to converge_time_s for W = 0).
  std::optional<double> converge_time_pointwise_s;
};

// t, position_error (|e_p|, m), velocity_error (|e_v|, m/s): one entry per step.
// diverged_at: index of the first diverged step (the series are then only used up to it),
// or empty. Metrics of a diverged filter are empty (there is no steady state).
FilterMetrics compute_metrics(const std::vector<double>& t,
                              const std::vector<double>& position_error,
                              const std::vector<double>& velocity_error,
                              std::optional<long> diverged_at, const MetricSettings& settings);

// Statistics of one metric over Monte-Carlo runs (runs where it is empty are counted apart).
struct MetricStats {
  long count = 0;  // runs with a value
  double mean = 0, std = 0, min = 0, max = 0;  // std: sample standard deviation (n − 1)
};
MetricStats compute_stats(const std::vector<std::optional<double>>& values);

// The nearest-rank q-quantile (0 < q ≤ 1) of a non-empty series: its ⌈q n⌉-th smallest value.
double nearest_rank_quantile(std::vector<double> values, double q);

// For the plots (docs/experiments.md "Plots"): the trailing RMS of x(t) over the last `window`
// seconds (the one the convergence time uses; fewer samples at the start), taken at every
// `stride`-th sample (0, stride, 2 stride, …); NaN from the first NaN of x on (a diverged filter).
std::vector<double> moving_rms_samples(const std::vector<double>& t, const std::vector<double>& x, double window,
                                       long stride);

}  // namespace hinf::sim
