#include "hinf/sim/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hinf::sim {
namespace {

// First t_k such that e(j) < threshold for all j ≥ k (scanning back from the end for the
// last sample at or above it); empty if the last sample is not below.
std::optional<double> settle_time(const std::vector<double>& t, const std::vector<double>& e, double threshold) {
  const std::size_t n = t.size();
  if (n == 0 || !(e[n - 1] < threshold)) return std::nullopt;
  std::size_t k = n;
  while (k > 0 && e[k - 1] < threshold) --k;
  return t[k];
}

// r(k) = sqrt(mean of e(j)² over t_j ∈ (t_k − window, t_k]); a running sum in long double
// (the squares span 1e4 m² to 1e-4 m², so cancellation in double would leave drift).
std::vector<double> trailing_rms(const std::vector<double>& t, const std::vector<double>& e, double window) {
  std::vector<double> r(t.size());
  long double sum = 0;
  std::size_t first = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    sum += static_cast<long double>(e[k]) * e[k];
    while (t[first] <= t[k] - window) {
      sum -= static_cast<long double>(e[first]) * e[first];
      ++first;
    }
    r[k] = std::sqrt(static_cast<double>(std::max(sum, 0.0L) / static_cast<long double>(k + 1 - first)));
  }
  return r;
}

}  // namespace

FilterMetrics compute_metrics(const std::vector<double>& t,
                              const std::vector<double>& position_error,
                              const std::vector<double>& velocity_error,
                              std::optional<long> diverged_at, const MetricSettings& settings) {
  FilterMetrics m;
  if (diverged_at) {
    m.diverged = true;
    m.diverged_at_s = t.at(static_cast<std::size_t>(*diverged_at));
    return m;
  }
  const std::size_t n = t.size();
  double sum_p = 0, sum_v = 0, max_p = 0;
  long count = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (t[k] < settings.steady_state_start_s) continue;
    sum_p += position_error[k] * position_error[k];
    sum_v += velocity_error[k] * velocity_error[k];
    max_p = std::max(max_p, position_error[k]);
    ++count;
  }
  if (count > 0) {
    m.position_rms_m = std::sqrt(sum_p / count);
    m.velocity_rms_mps = std::sqrt(sum_v / count);
    m.position_max_m = max_p;
  }
  m.converge_time_pointwise_s = settle_time(t, position_error, settings.converge_threshold_m);
  m.converge_time_s = settings.converge_window_s > 0
                          ? settle_time(t, trailing_rms(t, position_error, settings.converge_window_s),
                                        settings.converge_threshold_m)
                          : m.converge_time_pointwise_s;
  return m;
}

MetricStats compute_stats(const std::vector<std::optional<double>>& values) {
  MetricStats s;
  double sum = 0;
  for (const auto& v : values) {
    if (!v) continue;
    if (s.count == 0) s.min = s.max = *v;
    s.min = std::min(s.min, *v);
    s.max = std::max(s.max, *v);
    sum += *v;
    ++s.count;
  }
  if (s.count == 0) return s;
  if (s.min == s.max) {  // identical values: their mean and a zero spread exactly, not a rounded sum's
    s.mean = s.min;
    s.std = 0;
    return s;
  }
  s.mean = sum / s.count;
  double ss = 0;
  for (const auto& v : values)
    if (v) ss += (*v - s.mean) * (*v - s.mean);
  s.std = s.count > 1 ? std::sqrt(ss / (s.count - 1)) : 0.0;
  return s;
}

std::vector<double> moving_rms_samples(const std::vector<double>& t, const std::vector<double>& x, double window,
                                       long stride) {
  const std::vector<double> r = trailing_rms(t, x, window);
  std::vector<double> out;
  for (std::size_t k = 0; k < r.size(); k += static_cast<std::size_t>(stride)) out.push_back(r[k]);
  return out;
}

double nearest_rank_quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  const double rank = std::ceil(q * static_cast<double>(values.size()));
  return values[std::min(values.size() - 1, static_cast<std::size_t>(std::max(rank, 1.0)) - 1)];
}

}  // namespace hinf::sim
