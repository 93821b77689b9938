#include "hinf/sim/scenario.hpp"

#include <cmath>

namespace hinf::sim {

long Scenario::steps() const { return std::lround(duration / sample_time) + 1; }

MetricSettings Scenario::metric_settings() const {
  MetricSettings m;
  m.steady_state_start_s = steady_state_start ? *steady_state_start : 0.5 * duration;
  m.converge_threshold_m = converge_threshold_m;
  m.converge_window_s = converge_window_s;
  return m;
}

}  // namespace hinf::sim
