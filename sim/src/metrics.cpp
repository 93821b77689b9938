#include "hinf/sim/metrics.hpp"

#include <algorithm>
#include <cmath>

namespace hinf::sim {

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
  // Scan backwards for the last sample at or above the threshold.
  if (n > 0 && position_error[n - 1] < settings.converge_threshold_m) {
    std::size_t k = n;
    while (k > 0 && position_error[k - 1] < settings.converge_threshold_m) --k;
    m.converge_time_s = t[k];
  }
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
  s.mean = sum / s.count;
  double ss = 0;
  for (const auto& v : values)
    if (v) ss += (*v - s.mean) * (*v - s.mean);
  s.std = s.count > 1 ? std::sqrt(ss / (s.count - 1)) : 0.0;
  return s;
}

}  // namespace hinf::sim
