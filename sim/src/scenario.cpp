#include "hinf/sim/scenario.hpp"

#include <algorithm>
#include <cmath>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"

namespace hinf::sim {

std::string timing_problem(double duration, double sample_time) {
  const double ratio = duration / sample_time;
  if (!(ratio <= kMaxSimulationSteps))
    return "is " + hinf::number_text(ratio) + " sample times of " + hinf::number_text(sample_time) +
           " s; a run has at most " + hinf::number_text(kMaxSimulationSteps) + " samples";
  if (std::fabs(ratio - std::round(ratio)) > 1e-6 * std::max(1.0, ratio))
    return "must be a whole number of sample times (" + hinf::number_text(sample_time) + " s)";
  if (std::round(ratio) < 1)
    return "is shorter than one sample time (" + hinf::number_text(sample_time) + " s): a run needs at least one sample";
  return "";
}

double checked_duration(double duration, double sample_time) {
  const std::string problem = timing_problem(duration, sample_time);
  if (!problem.empty())
    throw hinf::Error(hinf::ErrorCode::InvalidInput, "--duration " + hinf::number_text(duration) + ": " + problem);
  return duration;
}

long Scenario::steps() const { return std::lround(duration / sample_time) + 1; }

MetricSettings Scenario::metric_settings() const {
  MetricSettings m;
  m.steady_state_start_s = steady_state_start ? *steady_state_start : 0.5 * duration;
  m.converge_threshold_m = converge_threshold_m;
  m.converge_window_s = converge_window_s;
  return m;
}

}  // namespace hinf::sim
