// Parsing only: YAML → HoldScenario (hold_scenario_yaml.hpp), with the project's one strict
// YAML reader. Angles are given in degrees in the file (keys *_deg_s, *_deg_s2).
#include "hinf/sim/hold_scenario_yaml.hpp"

#include <cmath>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "hinf/models/tumbling_hold.hpp"
#include "scenario_fields.hpp"
#include "scenario_paths.hpp"

namespace hinf::sim {

const char* to_string(ModulatorKind k) {
  return k == ModulatorKind::Ideal ? "ideal" : k == ModulatorKind::Pwm ? "pwm" : "pwpf";
}

namespace {

using hinf::models::kRadiansPerDegree;

// `a` a whole multiple of `b` (to 1e-9 relative), as the run's timing requires.
bool whole_multiple(double a, double b) {
  const double k = a / b;
  return std::abs(k - std::round(k)) <= 1e-9 * std::max(1.0, k) && std::round(k) >= 1;
}

void read_timing(const YamlMap& top, HoldScenario& s) {
  top.required("duration", "s");
  s.duration = top.positive("duration");
  s.integration_step = top.positive("integration_step", s.integration_step);
  s.control_sample_time = top.positive("control_sample_time", s.control_sample_time);
  if (!whole_multiple(s.control_sample_time, s.integration_step))
    top.fail_value("control_sample_time", s.control_sample_time,
                   "must be a whole multiple of integration_step " + number_text(s.integration_step));
  if (!whole_multiple(s.duration, s.control_sample_time))
    top.fail_value("duration", s.duration,
                   "must be a whole multiple of control_sample_time " + number_text(s.control_sample_time));
  const std::string too_long = integration_problem(s);
  if (!too_long.empty()) top.fail_value("duration", s.duration, too_long);
}

void read_target(const YamlMap& top, HoldScenario& s) {
  if (!top.has("target")) return;
  const YamlMap t = top.map("target", {"inertia", "initial_rate_deg_s", "orbit_rate", "mu"});
  s.inertia = scenario_vector3(t, "inertia", s.inertia);
  if (!(s.inertia.minCoeff() > 0)) t.fail("inertia", "the principal moments must be positive");
  const Eigen::Vector3d& J = s.inertia;
  if (J(0) > J(1) + J(2) || J(1) > J(0) + J(2) || J(2) > J(0) + J(1))
    t.fail("inertia", "violates the triangle inequality of a rigid body's principal moments");
  s.initial_rate = scenario_vector3(t, "initial_rate_deg_s", s.initial_rate / kRadiansPerDegree, kRadiansPerDegree);
  s.orbit_rate = t.positive("orbit_rate", s.orbit_rate);
  s.mu = t.positive("mu", s.mu);
}

void read_control(const YamlMap& top, HoldScenario& s) {
  s.servicer_mass = top.positive("servicer_mass", s.servicer_mass);
  s.hold_point = scenario_vector3(top, "hold_point", s.hold_point);
  s.initial_offset = scenario_vector3(top, "initial_offset", s.initial_offset);
  s.initial_velocity = scenario_vector3(top, "initial_velocity", s.initial_velocity);
  if (top.has("measurement")) s.measurement_sigma = top.map("measurement", {"sigma"}).nonnegative("sigma", s.measurement_sigma);
  // feedforward: true (at the target's initial rate), false, the nominal rate it assumes, or
  // {from: target_rate}
  s.nominal_rate = s.initial_rate;
  if (top.has("feedforward")) {
    const YAML::Node f = top.get("feedforward");
    if (f.IsMap()) {
      const YamlMap m = top.map("feedforward", {"rate_deg_s", "accel_deg_s2", "from"});
      if (m.has("from")) {
        m.choice("from", {"target_rate"});
        for (const char* key : {"rate_deg_s", "accel_deg_s2"})
          if (m.has(key)) m.fail(key, "not with from: target_rate (the rate is the target's, at each sample)");
        s.feedforward_from_target_rate = true;
      }
      s.nominal_rate = scenario_vector3(m, "rate_deg_s", s.nominal_rate / kRadiansPerDegree, kRadiansPerDegree);
      s.nominal_accel = scenario_vector3(m, "accel_deg_s2", s.nominal_accel, kRadiansPerDegree);
    } else {
      s.feedforward = top.boolean("feedforward", true);
    }
  }
  top.required("controller", "{file: a controller file} or {synthesize: a controller config}");
  const YamlMap c = top.map("controller", {"file", "synthesize"});
  if (c.has("file") == c.has("synthesize"))
    c.reader().fail(c.node(), "controller: needs exactly one of 'file' (hinf-controller/1) or 'synthesize' (a "
                              "controller config)");
  if (c.has("file")) s.controller.file_path = resolve_scenario_file(c, "file", s.path);
  else s.controller.synthesize_path = resolve_scenario_file(c, "synthesize", s.path);
}

// The PWM modulator's own rules (runtime/pulse_modulator.hpp) checked here, where they can name
// the scenario's keys: a started pulse fits in a period, and a period is at most 1e12 ticks.
void check_pwm_period(const YamlMap& where, const HoldScenario& s) {
  if (s.modulator != ModulatorKind::Pwm) return;
  if (!(s.thrusters.min_on_time <= s.pwm.period))
    where.reader().fail(where.node(), "thrusters.min_on_time = " + number_text(s.thrusters.min_on_time) +
                                          ": must be at most the PWM period " + number_text(s.pwm.period) + " s");
  if (!(s.pwm.period / s.integration_step <= 1e12))
    where.reader().fail(where.node(), "modulator.period = " + number_text(s.pwm.period) +
                                          ": at most 1e12 integration steps of " + number_text(s.integration_step) + " s");
}

void read_actuators(const YamlMap& top, HoldScenario& s) {
  if (top.has("thrusters")) {
    const YamlMap t = top.map("thrusters", {"force", "min_on_time"});
    s.thrusters.force = t.positive("force", s.thrusters.force);
    s.thrusters.min_on_time = t.nonnegative("min_on_time", s.thrusters.min_on_time);
  }
  s.pwm.thruster = s.pwpf.thruster = s.thrusters;
  s.pwm.resolution = s.integration_step;
  s.pwm.carry_limit = s.thrusters.force * s.thrusters.min_on_time;
  if (!std::isfinite(s.pwm.carry_limit))  // the impulse of one shortest pulse
    top.fail_value("thrusters", s.pwm.carry_limit, "force x min_on_time (the shortest pulse's impulse) must be finite");
  if (!top.has("modulator")) {
    check_pwm_period(top, s);
    return;
  }
  const YamlMap m = top.map("modulator", {"type", "period", "carry_remainder", "Km", "tau", "u_on", "u_off"});
  m.required("type", "ideal, pwm or pwpf");
  const std::string type = m.choice("type", {"ideal", "pwm", "pwpf"});
  s.modulator = type == "ideal" ? ModulatorKind::Ideal : type == "pwm" ? ModulatorKind::Pwm : ModulatorKind::Pwpf;
  for (const char* key : {"period", "carry_remainder"})
    if (m.has(key) && s.modulator != ModulatorKind::Pwm) m.fail(key, "only with modulator.type: pwm");
  for (const char* key : {"Km", "tau", "u_on", "u_off"})
    if (m.has(key) && s.modulator != ModulatorKind::Pwpf) m.fail(key, "only with modulator.type: pwpf");
  if (s.modulator == ModulatorKind::Pwm) {
    s.pwm.period = m.positive("period", s.pwm.period);
    s.pwm.carry_remainder = m.boolean("carry_remainder", s.pwm.carry_remainder);
    if (!whole_multiple(s.pwm.period, s.control_sample_time))
      m.fail_value("period", s.pwm.period,
                   "must be a whole multiple of control_sample_time " + number_text(s.control_sample_time));
    check_pwm_period(m, s);
  } else if (s.modulator == ModulatorKind::Pwpf) {
    s.pwpf.Km = m.positive("Km", s.pwpf.Km);
    s.pwpf.tau = m.positive("tau", s.pwpf.tau);
    s.pwpf.u_on = m.positive("u_on", s.pwpf.u_on);
    s.pwpf.u_off = m.nonnegative("u_off", s.pwpf.u_off);
    if (!(s.pwpf.u_off < s.pwpf.u_on)) m.fail_value("u_off", s.pwpf.u_off, "must be below u_on " + number_text(s.pwpf.u_on));
  }
}

void read_metrics(const YamlMap& top, HoldScenario& s) {
  if (!top.has("metrics")) return;
  const YamlMap m = top.map("metrics", {"steady_state_start", "settle_threshold"});
  s.steady_state_start = m.nonnegative("steady_state_start", s.steady_state_start);
  if (s.steady_state_start >= s.duration)
    m.fail_value("steady_state_start", s.steady_state_start, "must be before the end, duration " + number_text(s.duration));
  s.settle_threshold = m.positive("settle_threshold", s.settle_threshold);
}

}  // namespace

HoldScenario parse_hold_scenario(const std::string& text, const std::string& source_name) {
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(text, "empty scenario; expected a map with scenario: tumbling_hold");
  const YamlMap top = reader.map(root, "", {"scenario", "duration", "integration_step", "control_sample_time", "target",
                                            "servicer_mass", "hold_point", "initial_offset", "initial_velocity",
                                            "measurement", "feedforward", "controller", "thrusters", "modulator",
                                            "metrics", "plots"});
  HoldScenario s;
  s.path = source_name;
  read_timing(top, s);
  read_target(top, s);
  read_control(top, s);
  read_actuators(top, s);
  read_metrics(top, s);
  s.plots = top.boolean("plots", s.plots);
  if (s.steady_state_start >= s.duration) s.steady_state_start = s.duration / 2;
  return s;
}

}  // namespace hinf::sim
