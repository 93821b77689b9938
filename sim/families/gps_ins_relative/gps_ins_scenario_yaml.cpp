// Parsing only: YAML → GpsInsExperiment (gps_ins_scenario_yaml.hpp), with the project's one
// strict YAML reader.
#include "hinf/sim/gps_ins_scenario_yaml.hpp"

#include <cmath>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "scenario_fields.hpp"

namespace hinf::sim {

namespace {

using models::kRadiansPerDegree;
constexpr double kDegreesPerHour = kRadiansPerDegree / 3600;  // rad/s per °/h

void read_timing(const YamlMap& top, GpsInsScenario& s) {
  read_sampled_timing(top, s.duration, s.sample_time, s.truth_substeps);
}

void read_orbit(const YamlMap& top, GpsInsScenario& s) {
  if (top.has("orbit")) {
    const YamlMap o = top.map("orbit", {"radius", "mu", "inclination_deg", "raan_deg", "arg_lat0_deg"});
    s.orbit_radius = o.positive("radius", s.orbit_radius);
    s.mu = o.positive("mu", s.mu);
    s.inclination = o.finite("inclination_deg", s.inclination / kRadiansPerDegree) * kRadiansPerDegree;
    s.raan = o.finite("raan_deg", s.raan / kRadiansPerDegree) * kRadiansPerDegree;
    s.arg_lat0 = o.finite("arg_lat0_deg", s.arg_lat0 / kRadiansPerDegree) * kRadiansPerDegree;
  }
  if (top.has("truth_dynamics"))
    s.truth_dynamics = top.choice("truth_dynamics", {"nonlinear", "cw"}) == "cw" ? GpsInsTruthDynamics::Cw
                                                                                 : GpsInsTruthDynamics::Nonlinear;
  if (top.has("flyaround_frame")) top.map("flyaround_frame", {"rate"}).choice("rate", {"orbit_rate"});
}

void read_relative(const YamlMap& top, GpsInsScenario& s) {
  if (!top.has("relative")) return;
  const YamlMap r = top.map("relative", {"initial_position", "initial_velocity", "accel_perturbation_sigma"});
  s.initial_position = scenario_vector3(r, "initial_position", s.initial_position);
  if (s.initial_position.norm() == 0) r.fail("initial_position", "must not be the target's centre");
  if (r.has("initial_velocity")) {
    if (r.get("initial_velocity").IsScalar()) {
      r.choice("initial_velocity", {"drift_free"});
      s.initial_velocity_drift_free = true;
    } else {
      s.initial_velocity = scenario_vector3(r, "initial_velocity", s.initial_velocity);
      s.initial_velocity_drift_free = false;
    }
  }
  if (s.initial_position.cross(s.initial_velocity_used()).norm() <= 1e-12 * s.initial_position.norm())
    r.fail("initial_velocity", "is parallel to initial_position: no fly-around plane");
  s.accel_sigma = standard_deviation(r, "accel_perturbation_sigma", s.accel_sigma, 1.0, ZeroSigma::Allowed);
}

void read_attitude(const YamlMap& top, GpsInsScenario& s) {
  if (!top.has("attitude")) return;
  const YamlMap a = top.map("attitude", {"initial_euler312_deg", "initial_rate_deg_s", "inertia_nominal",
                                         "inertia_products_fraction", "inertia_products_signs",
                                         "torque_disturbance_sigma", "control"});
  s.initial_euler312 = scenario_vector3(a, "initial_euler312_deg", s.initial_euler312 / kRadiansPerDegree, kRadiansPerDegree);
  s.initial_rate = scenario_vector3(a, "initial_rate_deg_s", s.initial_rate / kRadiansPerDegree, kRadiansPerDegree);
  s.inertia_nominal = scenario_vector3(a, "inertia_nominal", s.inertia_nominal);
  const Eigen::Vector3d& J = s.inertia_nominal;
  if (!(J.minCoeff() > 0)) a.fail("inertia_nominal", "the principal moments must be positive");
  if (J(0) > J(1) + J(2) || J(1) > J(0) + J(2) || J(2) > J(0) + J(1))
    a.fail("inertia_nominal", "violates the triangle inequality of a rigid body's principal moments");
  s.inertia_products_fraction = a.nonnegative("inertia_products_fraction", s.inertia_products_fraction);
  s.inertia_products_signs = scenario_vector3(a, "inertia_products_signs", s.inertia_products_signs);
  for (int i = 0; i < 3; ++i)
    if (std::abs(s.inertia_products_signs(i)) != 1) a.fail("inertia_products_signs", "each entry must be 1 or -1");
  if (Eigen::LLT<Eigen::Matrix3d>(s.inertia_true()).info() != Eigen::Success)
    a.fail_value("inertia_products_fraction", s.inertia_products_fraction,
                 "makes the true inertia not positive definite");
  s.torque_sigma = standard_deviation(a, "torque_disturbance_sigma", s.torque_sigma, 1.0, ZeroSigma::Allowed);
  if (a.has("control")) {
    const YamlMap c = a.map("control", {"law", "kp", "kd", "on"});
    if (c.has("law"))
      s.control = c.choice("law", {"pd_feedforward", "none"}) == "none" ? AttitudeControlLaw::None
                                                                        : AttitudeControlLaw::PdFeedforward;
    s.kp = c.nonnegative("kp", s.kp);
    s.kd = c.nonnegative("kd", s.kd);
    if (c.has("on")) c.choice("on", {"truth"});
  }
}

void read_gyro(const YamlMap& top, GpsInsScenario& s) {
  if (!top.has("gyro")) return;
  const YamlMap g = top.map("gyro", {"noise_deg_h", "bias_initial_deg_h", "bias_rw_deg_h_sqrt_h"});
  s.gyro_noise_sigma =
      standard_deviation(g, "noise_deg_h", s.gyro_noise_sigma / kDegreesPerHour, kDegreesPerHour, ZeroSigma::Refused) *
      kDegreesPerHour;
  s.gyro_bias_initial = scenario_vector3(g, "bias_initial_deg_h", s.gyro_bias_initial / kDegreesPerHour, kDegreesPerHour);
  // (°/h)/√h → rad/s^1.5: ÷ 60 (√3600 s)
  s.gyro_bias_walk_sigma =
      standard_deviation(g, "bias_rw_deg_h_sqrt_h", s.gyro_bias_walk_sigma * 60 / kDegreesPerHour,
                         kDegreesPerHour / 60, ZeroSigma::Allowed) *
      kDegreesPerHour / 60;
}

void read_gps(const YamlMap& top, GpsInsScenario& s) {
  if (!top.has("gps")) return;
  const YamlMap g = top.map("gps", {"constellation", "satellites_el_az_deg", "distance", "frequency",
                                    "pseudorange_sigma", "phase_sigma", "phase_sigma_unit", "phase_mode",
                                    "antennas_body"});
  if (g.has("constellation")) g.choice("constellation", {"lvlh_fixed"});
  if (g.has("satellites_el_az_deg")) {
    const Eigen::MatrixXd m = g.matrix("satellites_el_az_deg", models::kGpsInsSatellites, 2, MatrixForms::RowsOnly);
    for (int j = 0; j < models::kGpsInsSatellites; ++j) {
      if (!(m(j, 0) > 0 && m(j, 0) <= 90))
        g.fail("satellites_el_az_deg", "row " + std::to_string(j + 1) + ": the elevation must be in (0, 90]");
      s.satellites_el_az[j] = m.row(j).transpose() * kRadiansPerDegree;
    }
  }
  s.satellite_distance = g.positive("distance", s.satellite_distance);
  s.carrier_frequency = g.positive("frequency", s.carrier_frequency);
  s.pseudorange_sigma = standard_deviation(g, "pseudorange_sigma", s.pseudorange_sigma, 1.0, ZeroSigma::Refused);
  s.phase_sigma = standard_deviation(g, "phase_sigma", s.phase_sigma, 1.0, ZeroSigma::Refused);
  if (g.has("phase_sigma_unit") && g.choice("phase_sigma_unit", {"cycles", "m"}) == "m")
    s.phase_sigma *= s.carrier_frequency / models::kSpeedOfLight;
  if (g.has("phase_mode") && g.choice("phase_mode", {"single_difference", "double_difference"}) == "double_difference")
    s.phase_mode = GpsInsScenario::PhaseMode::DoubleDifference;
  if (g.has("antennas_body")) {
    const Eigen::MatrixXd m = g.matrix("antennas_body", 3, 3, MatrixForms::RowsOnly);
    for (int k = 0; k < 3; ++k) s.antennas[k] = m.row(k).transpose();
  }
  for (const Eigen::Vector3d& b : s.baselines())
    if (b.norm() == 0) g.fail("antennas_body", "two antennas coincide: a baseline is zero");
}

void read_estimate(const YamlMap& top, GpsInsInitialError& e) {
  if (!top.has("estimate")) return;
  const YamlMap m = top.map("estimate", {"initial_error_sigma", "sample_initial_error"});
  if (m.has("initial_error_sigma")) {
    const YamlMap i = m.map("initial_error_sigma", {"position", "velocity", "attitude_deg", "rate_deg_s", "bias_deg_h"});
    const auto sigma = [&i](const char* key, double fallback, double to_si) {
      return standard_deviation(i, key, fallback, to_si, ZeroSigma::Refused);
    };
    e.position = sigma("position", e.position, 1.0);
    e.velocity = sigma("velocity", e.velocity, 1.0);
    e.attitude = sigma("attitude_deg", e.attitude / kRadiansPerDegree, kRadiansPerDegree) * kRadiansPerDegree;
    e.rate = sigma("rate_deg_s", e.rate / kRadiansPerDegree, kRadiansPerDegree) * kRadiansPerDegree;
    e.bias = sigma("bias_deg_h", e.bias / kDegreesPerHour, kDegreesPerHour) * kDegreesPerHour;
  }
  e.sample = m.boolean("sample_initial_error", e.sample);
}

// A, C, L of a REKF given as matrices (docs/experiments.md "Seed 003"), each instead of its
// (197) form: not with the factor it replaces.
void read_explicit_uncertainty(const YamlMap& f, int nz, GpsInsFilterSettings& s) {
  const auto exclusive = [&](const char* key, const char* replaced) {
    if (f.has(key) && f.has(replaced)) f.fail(replaced, std::string("give ") + key + " or " + replaced + ", not both");
  };
  exclusive("A", "kappa_A");
  exclusive("C", "kappa_C");
  if (f.has("A")) s.A = f.matrix("A", 15, 15);
  if (f.has("L")) s.L = f.matrix("L", 15, 15);
  if (f.has("C")) s.C = f.matrix("C", nz, 15, MatrixForms::RowsOnly);
}

GpsInsFilterSettings read_gps_ins_filter(const YamlMap& filters, const std::string& name, int nz) {
  require_column_name(filters, name, "a filter's name");
  const YamlMap f = filters.map(name, {"type", "jacobian", "propagation", "process_noise",
                                       "inertia_uncertainty_fraction", "gamma", "scale_factor", "kappa_A", "kappa_C",
                                       "A", "C", "L"},
                                EmptyMap::Allowed);
  GpsInsFilterSettings s;
  s.name = name;
  std::string type = name == "ekf" || name == "rekf" ? name : "";
  if (f.has("type")) type = f.choice("type", {"ekf", "rekf"});
  if (type.empty()) f.reader().fail(f.node(), "filters." + name + ": needs type: ekf or rekf");
  s.kind = type == "rekf" ? GpsInsFilterKind::Rekf : GpsInsFilterKind::Ekf;
  if (f.has("jacobian"))
    s.jacobian = f.choice("jacobian", {"full", "paper"}) == "paper" ? models::GpsInsJacobian::Paper
                                                                     : models::GpsInsJacobian::Full;
  if (f.has("propagation"))
    s.propagation = f.choice("propagation", {"exact", "euler"}) == "euler" ? models::GpsInsPropagation::Euler
                                                                            : models::GpsInsPropagation::Exact;
  if (f.has("process_noise")) s.zoh_process_noise = f.choice("process_noise", {"paper_G", "zoh"}) == "zoh";
  s.inertia_uncertainty_fraction = f.nonnegative("inertia_uncertainty_fraction", s.inertia_uncertainty_fraction);
  for (const char* key : {"gamma", "scale_factor", "kappa_A", "kappa_C", "A", "C", "L"})
    if (f.has(key) && s.kind != GpsInsFilterKind::Rekf) f.fail(key, "only with type: rekf");
  read_explicit_uncertainty(f, nz, s);
  s.gamma = f.positive("gamma", s.gamma);
  s.scale_factor = f.positive("scale_factor", s.scale_factor);
  s.kappa_A = f.nonnegative("kappa_A", s.kappa_A);
  s.kappa_C = f.nonnegative("kappa_C", s.kappa_C);
  return s;
}

void read_gps_ins_filters(const YamlMap& top, const GpsInsScenario& scenario, std::vector<GpsInsFilterSettings>& out) {
  const int nz = scenario.phase_mode == GpsInsScenario::PhaseMode::DoubleDifference
                     ? models::GpsInsDoubleDifferenceMeasurement::NZ
                     : models::GpsInsMeasurement::NZ;
  read_named_filters(top, static_cast<std::size_t>(kMaxGpsInsFilters), "ekf, rekf, …",
                     [&](const YamlMap& filters, const std::string& name) { out.push_back(read_gps_ins_filter(filters, name, nz)); });
}

void read_metrics(const YamlMap& top, const GpsInsScenario& s, GpsInsRunOptions& o,
                  std::vector<double>& table1_fractions) {
  o.window_end = s.duration;
  o.window_start = std::min(o.window_start, s.duration / 2);
  if (!top.has("metrics")) return;
  const YamlMap m = top.map("metrics", {"steady_state_window", "attitude_error", "table1_products_fractions"});
  if (m.has("steady_state_window")) {
    const Eigen::VectorXd w = m.vector("steady_state_window", 2);
    if (!(w.allFinite() && w(0) >= 0 && w(0) < w(1) && w(1) <= s.duration))
      m.fail("steady_state_window", "must be [start, end] with 0 <= start < end <= duration " + number_text(s.duration));
    o.window_start = w(0);
    o.window_end = w(1);
  }
  if (m.has("attitude_error")) m.choice("attitude_error", {"euler312"});
  if (m.has("table1_products_fractions")) {
    const Eigen::VectorXd p = m.vector("table1_products_fractions");
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      if (p(i) < 0 || p(i) >= 1 || (i > 0 && p(i) <= p(i - 1)))
        m.fail("table1_products_fractions", "must be increasing fractions in [0, 1), got " + number_text(p(i)) +
                                                " at index " + std::to_string(i));
      GpsInsScenario with_p = s;
      with_p.inertia_products_fraction = p(i);
      if (Eigen::LLT<Eigen::Matrix3d>(with_p.inertia_true()).info() != Eigen::Success)
        m.fail("table1_products_fractions", number_text(p(i)) + " at index " + std::to_string(i) +
                                                " makes the true inertia not positive definite");
      table1_fractions.push_back(p(i));
    }
  }
}

}  // namespace

GpsInsExperiment parse_gps_ins_scenario(const std::string& text, const std::string& source_name) {
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(text, "empty scenario; expected a map with scenario: gps_ins_relative");
  const YamlMap top = reader.map(root, "", {"scenario", "duration", "sample_time", "truth_substeps", "orbit",
                                            "truth_dynamics", "relative", "flyaround_frame", "attitude", "gyro", "gps",
                                            "estimate", "filters", "metrics", "plots"});
  GpsInsExperiment e;
  e.path = source_name;
  GpsInsScenario& s = e.scenario;
  read_timing(top, s);
  read_orbit(top, s);
  read_relative(top, s);
  read_attitude(top, s);
  read_gyro(top, s);
  read_gps(top, s);
  read_estimate(top, e.options.initial_error);
  read_gps_ins_filters(top, s, e.filters);
  read_metrics(top, s, e.options, e.table1_fractions);
  e.plots = top.boolean("plots", e.plots);
  return e;
}

}  // namespace hinf::sim
