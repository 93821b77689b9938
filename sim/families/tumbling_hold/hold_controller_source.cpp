// obtain_hold_controller (hold_controller_source.hpp).
#include "hinf/sim/hold_controller_source.hpp"

#include <hinf/common/error.hpp>
#include <hinf/common/input_file.hpp>
#include <hinf/common/number_text.hpp>
#include <hinf/runtime_yaml/controller_file.hpp>
#include <hinf/synth/controller_config.hpp>
#include <hinf/synth/controller_output.hpp>

#include <cmath>

namespace hinf::sim {
namespace {

// The run feeds e = y − ρ* (3) and applies U (3); a discrete controller must run at T_c.
hinf::Controller at_control_rate(const hinf::Controller& K, std::optional<double> period, double T_c,
                                 const std::string& origin) {
  if (K.B_K.cols() != 3 || K.C_K.rows() != 3)
    throw hinf::Error(hinf::ErrorCode::InvalidInput,
                      origin + ": the controller has " + std::to_string(K.B_K.cols()) + " inputs and " +
                          std::to_string(K.C_K.rows()) +
                          " outputs; tumbling_hold needs 3 and 3 (position error in, force out)");
  if (!period) return hinf::tustin(K, T_c);
  if (std::abs(*period - T_c) > 1e-9 * T_c)
    throw hinf::Error(hinf::ErrorCode::InvalidInput,
                      origin + ": a discrete-time controller of period " + number_text(*period) +
                          " s cannot run at control_sample_time " + number_text(T_c) + " s");
  return K;
}

}  // namespace

ObtainedController obtain_hold_controller(const ControllerSource& source, double T_c, const StatusLog& log) {
  ObtainedController out;
  if (!source.file_path.empty()) {
    out.controller_yaml = hinf::read_input_file(source.file_path, "controller file", hinf::kMaxGainsBytes);
    const auto file = hinf::runtime_yaml::parse_controller_yaml(out.controller_yaml, source.file_path);
    out.origin = "controller file " + source.file_path;
    out.discrete = at_control_rate({file.A_K, file.B_K, file.C_K, file.D_K}, file.sample_time, T_c, out.origin);
    out.gamma = file.gamma;
  } else {
    const auto config = hinf::synth::parse_controller_config(hinf::synth::read_config_bytes(source.synthesize_path),
                                                             source.synthesize_path);
    if (log) log("synthesising the controller from " + source.synthesize_path + " ...");
    const auto r = hinf::synth::synthesize_controller(config.plant, config.settings, config.design);
    const bool discrete = config.plant.time == hinf::TimeDomain::Discrete;
    const std::optional<double> period = discrete ? std::optional<double>(config.plant.sample_time) : std::nullopt;
    out.controller_yaml = hinf::synth::format_controller_yaml(r, config.plant, config.design,
                                                              {source.synthesize_path, config.sha256, period});
    out.origin = "synthesised from " + source.synthesize_path;
    out.discrete = at_control_rate(r.controller, period, T_c, out.origin);
    out.gamma = r.gamma;
  }
  if (!out.discrete.A_K.allFinite())  // Tustin at a controller pole at s = 2/T_c
    throw hinf::Error(hinf::ErrorCode::InvalidInput, out.origin + ": Tustin's rule at " + number_text(T_c) +
                                                         " s is undefined for this controller (a pole at s = 2/T)");
  return out;
}

}  // namespace hinf::sim
