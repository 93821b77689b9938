#include "hinf/sim/hold_scenario.hpp"

#include <cmath>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/sim/scenario.hpp"

namespace hinf::sim {

long HoldScenario::control_steps() const { return std::lround(duration / control_sample_time) + 1; }
long HoldScenario::ticks_per_control() const { return std::lround(control_sample_time / integration_step); }

std::string integration_problem(const HoldScenario& s) {
  if (!(s.duration / s.integration_step > kMaxIntegrationSteps)) return "";
  return "needs more than " + number_text(kMaxIntegrationSteps) + " integration steps of " +
         number_text(s.integration_step) + " s";
}

void set_hold_duration(HoldScenario& s, double duration) {
  s.duration = checked_duration(duration, s.control_sample_time);
  const std::string too_long = integration_problem(s);
  if (!too_long.empty())
    throw hinf::Error(hinf::ErrorCode::InvalidInput, "--duration " + number_text(duration) + ": " + too_long);
  if (s.steady_state_start >= s.duration) s.steady_state_start = s.duration / 2;
}

}  // namespace hinf::sim
