// Obtaining a tumbling_hold run's controller: read a controller file
// (hinf::runtime_yaml::load_controller_file) or synthesise one now from a controller config
// (hinf::synth::synthesize_controller, docs/maths.md §26–§27); a continuous-time controller
// is discretised by Tustin's rule (docs/maths.md (161)) at the control period.
#pragma once
#include <optional>
#include <string>

#include "hinf/models/controller.hpp"
#include "hinf/sim/hold_scenario.hpp"
#include "hinf/sim/status_log.hpp"

namespace hinf::sim {

struct ObtainedController {
  hinf::Controller discrete;    // at the control period
  std::optional<double> gamma;  // the certified bound, if known
  std::string controller_yaml;  // the controller file: its bytes, or the synthesis library's writer
  std::string origin;           // "controller file PATH" or "synthesised from PATH", and the discretisation
};

// hinf::Error: InvalidInput for a bad file or config, a controller that is not 3 in, 3 out,
// or a discrete one of another period; a synthesis may also end Infeasible, CheckFailed or
// NumericalFailure. `log` (may be empty) hears that a synthesis starts.
ObtainedController obtain_hold_controller(const ControllerSource& source, double control_sample_time,
                                          const StatusLog& log);

}  // namespace hinf::sim
