// Parsing only: YAML → ManoeuvringExperiment (manoeuvring_scenario_yaml.hpp), with the project's
// one strict YAML reader.
#include "hinf/sim/manoeuvring_scenario_yaml.hpp"

#include <cmath>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "scenario_fields.hpp"

namespace hinf::sim {

namespace {

using models::kRadiansPerDegree;

constexpr double kMaxSemiMajorAxis = 1e10;  // m (26 times the Moon's distance)

// An elliptic orbit whose perigee is above the Earth's surface.
models::OrbitalElements read_orbit(const YamlMap& orbits, const char* who, const ManoeuvringScenario& s,
                                   const models::OrbitalElements& fallback) {
  if (!orbits.has(who)) return fallback;
  const YamlMap o = orbits.map(
      who, {"a", "e", "inclination_deg", "raan_deg", "arg_perigee_deg", "true_anomaly_deg"});
  models::OrbitalElements el;
  el.a = o.positive("a");
  if (el.a <= s.earth_radius)
    o.fail_value("a", el.a, "must be above the Earth's radius " + number_text(s.earth_radius) + " m");
  if (el.a > kMaxSemiMajorAxis) o.fail_value("a", el.a, "must be at most 1e10 m");
  el.e = o.nonnegative("e", 0.0);
  if (el.e >= 1) o.fail_value("e", el.e, "must be in [0, 1): elliptic orbits only");
  if (el.a * (1 - el.e) <= s.earth_radius)
    o.fail_value("e", el.e,
                 "puts the perigee a(1 − e) = " + number_text(el.a * (1 - el.e)) + " m inside the Earth (radius " +
                     number_text(s.earth_radius) + " m)");
  el.inclination = o.finite("inclination_deg", 0.0) * kRadiansPerDegree;
  el.raan = o.finite("raan_deg", 0.0) * kRadiansPerDegree;
  el.arg_perigee = o.finite("arg_perigee_deg", 0.0) * kRadiansPerDegree;
  el.true_anomaly = o.finite("true_anomaly_deg") * kRadiansPerDegree;
  return el;
}

void read_orbits(const YamlMap& top, ManoeuvringScenario& s) {
  s.mu = top.positive("mu", s.mu);
  if (!top.has("orbits")) return;
  const YamlMap o = top.map("orbits", {"target", "chaser"});
  s.target = read_orbit(o, "target", s, s.target);
  s.chaser = read_orbit(o, "chaser", s, s.chaser);
  const models::OrbitState t = models::state_from_elements(s.target, s.mu);
  const models::OrbitState c = models::state_from_elements(s.chaser, s.mu);
  if ((t.r - c.r).norm() < 1.0)
    o.reader().fail(o.node(), "orbits: target and chaser are within 1 m of each other at t = 0 (no line of sight)");
}

// One thrust arc {start, end, accel, frame}, inside [0, duration).
ThrustArc read_arc(const YamlReader& reader, const YAML::Node& node, const std::string& path, double duration) {
  const YamlMap m = reader.map(node, path, {"start", "end", "accel", "frame"});
  ThrustArc a;
  a.start = m.nonnegative("start");
  a.end = m.positive("end");
  if (a.start >= duration) m.fail_value("start", a.start, "must be before the end of the run, " + number_text(duration) + " s");
  if (a.end <= a.start) m.fail_value("end", a.end, "must be after start " + number_text(a.start));
  if (a.end > duration) m.fail_value("end", a.end, "must be at most the duration " + number_text(duration) + " s");
  a.accel = scenario_vector3(m, "accel", a.accel);
  if (m.has("frame")) a.frame = m.choice("frame", {"own_lvlh", "lvlh0"}) == "lvlh0" ? ThrustFrame::Lvlh0 : ThrustFrame::OwnLvlh;
  return a;
}

std::vector<ThrustArc> read_arcs(const YamlMap& m, const char* who, double duration, std::vector<ThrustArc> fallback) {
  if (!m.has(who)) return fallback;
  const YAML::Node node = m.get(who);
  std::vector<ThrustArc> arcs;
  if (node.IsSequence() && node.size() == 0) return arcs;
  for (const auto& [item, path] : m.reader().one_or_list(node, m.path_of(who)))
    arcs.push_back(read_arc(m.reader(), item, path, duration));
  return arcs;
}

void read_manoeuvres(const YamlMap& top, ManoeuvringScenario& s) {
  if (!top.has("manoeuvres")) return;
  const YamlMap m = top.map("manoeuvres", {"target", "chaser"}, EmptyMap::Allowed);
  s.target_manoeuvres = read_arcs(m, "target", s.duration, s.target_manoeuvres);
  s.chaser_manoeuvres = read_arcs(m, "chaser", s.duration, s.chaser_manoeuvres);
}

// {type: gaussian, sigma: σ}
double read_noise(const YamlMap& m, const char* key, double fallback) {
  if (!m.has(key)) return fallback;
  const YamlMap n = m.map(key, {"type", "sigma"});
  if (n.has("type")) n.choice("type", {"gaussian"});
  return n.positive("sigma");
}

void read_sensors(const YamlMap& top, ManoeuvringScenario& s) {
  if (top.has("chaser_navigation")) {
    const YamlMap n = top.map("chaser_navigation", {"position_sigma", "velocity_sigma"});
    s.navigation_position_sigma = n.nonnegative("position_sigma", s.navigation_position_sigma);
    s.navigation_velocity_sigma = n.nonnegative("velocity_sigma", s.navigation_velocity_sigma);
  }
  if (!top.has("measurement")) return;
  const YamlMap m = top.map("measurement", {"convention", "range", "azimuth", "elevation", "noise"});
  if (m.has("convention"))
    s.convention = m.choice("convention", {"z_up", "z_down"}) == "z_up" ? models::ElevationConvention::ZUp
                                                                         : models::ElevationConvention::ZDown;
  s.measurement_sigma(0) = read_noise(m, "range", s.measurement_sigma(0));
  s.measurement_sigma(1) = read_noise(m, "azimuth", s.measurement_sigma(1));
  s.measurement_sigma(2) = read_noise(m, "elevation", s.measurement_sigma(2));
  s.noise = m.boolean("noise", s.noise);
}

Eigen::Matrix<double, 6, 1> read_sigma6(const YamlMap& m, const char* key, const Eigen::Matrix<double, 6, 1>& fallback,
                                        bool positive) {
  if (!m.has(key)) return fallback;
  const Eigen::VectorXd v = m.vector(key, 6);
  for (int i = 0; i < 6; ++i)
    if (!std::isfinite(v(i)) || v(i) < 0 || (positive && v(i) == 0))
      m.fail(key, "entry " + std::to_string(i + 1) + " is " + number_text(v(i)) + "; every entry must be " +
                      (positive ? "> 0" : ">= 0"));
  return v;
}

void read_estimate(const YamlMap& top, ManoeuvringEstimate& e) {
  if (!top.has("estimate")) return;
  const YamlMap m = top.map("estimate", {"initial_error_sigma", "sigma"});
  e.initial_error_sigma = read_sigma6(m, "initial_error_sigma", e.initial_error_sigma, false);
  e.sigma = read_sigma6(m, "sigma", e.sigma, true);
}

void read_detector(const YamlMap& f, ManoeuvreFilterSettings& s) {
  if (!f.has("detector")) return;
  const YamlMap d = f.map("detector", {"type", "window", "p_false_alarm"});
  if (d.choice("type", {"none", "nis_window"}) == "none") {
    if (d.has("window") || d.has("p_false_alarm")) d.fail(d.has("window") ? "window" : "p_false_alarm", "only with type: nis_window");
    return;
  }
  s.detector_window = d.integer("window", 10);
  if (s.detector_window < 1 || s.detector_window > 10000) d.fail("window", "must be in 1…10000 samples");
  s.detector_false_alarm = d.positive("p_false_alarm", s.detector_false_alarm);
  if (s.detector_false_alarm >= 1) d.fail_value("p_false_alarm", s.detector_false_alarm, "must be in (0, 1)");
}

ManoeuvreFilterSettings read_manoeuvre_filter(const YamlMap& filters, const std::string& name) {
  require_column_name(filters, name, "a filter's name");
  const YamlMap f = filters.map(name, {"transition", "process_noise_psd", "predict_with_chaser_control",
                                       "maneuver_covariance", "exact_substeps", "detector"},
                                EmptyMap::Allowed);
  ManoeuvreFilterSettings s;
  s.name = name;
  if (f.has("transition")) {
    const std::string t = f.choice("transition", {"frozen", "frozen_midpoint", "exact", "cw"});
    s.model.transition = t == "frozen"            ? models::RelativeTransition::Frozen
                         : t == "frozen_midpoint" ? models::RelativeTransition::FrozenMidpoint
                         : t == "exact"           ? models::RelativeTransition::Exact
                                                  : models::RelativeTransition::Cw;
  }
  s.model.process_noise_psd = f.positive("process_noise_psd", s.model.process_noise_psd);
  s.predict_with_chaser_control = f.boolean("predict_with_chaser_control", s.predict_with_chaser_control);
  if (f.has("maneuver_covariance")) {
    const std::string c = f.choice("maneuver_covariance", {"paper", "innovation", "both"});
    s.covariance = c == "paper" ? ManoeuvreCovariance::Paper
                   : c == "innovation" ? ManoeuvreCovariance::Innovation
                                       : ManoeuvreCovariance::Both;
  }
  s.model.exact_substeps = f.integer("exact_substeps", s.model.exact_substeps);
  if (s.model.exact_substeps < 1 || s.model.exact_substeps > 100000) f.fail("exact_substeps", "must be in 1…100000");
  read_detector(f, s);
  return s;
}

void read_manoeuvre_filters(const YamlMap& top, std::vector<ManoeuvreFilterSettings>& out) {
  read_named_filters(top, static_cast<std::size_t>(kMaxManoeuvringFilters), "transient, …",
                     [&](const YamlMap& filters, const std::string& name) { out.push_back(read_manoeuvre_filter(filters, name)); });
}

// windows: {name: [start, end]}, 0 ≤ start < end ≤ duration.
void read_metrics(const YamlMap& top, const ManoeuvringScenario& s, ManoeuvringRunOptions& o) {
  if (!top.has("metrics")) return;
  const YamlMap m = top.map("metrics", {"windows", "maneuver_tolerance"});
  o.maneuver_tolerance = m.positive("maneuver_tolerance", o.maneuver_tolerance);
  if (!m.has("windows")) return;
  const YAML::Node node = m.get("windows");
  if (!node.IsMap() || node.size() == 0) m.reader().fail(node, m.path_of("windows") + ": must be a map of names to [start, end]");
  if (node.size() > 16) m.reader().fail(node, m.path_of("windows") + ": at most 16 windows");
  const YamlMap windows(m.reader(), node, m.path_of("windows"));
  o.windows.clear();
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) m.reader().fail(kv.first, m.path_of("windows") + ": a window's name must be a word");
    const std::string name = kv.first.Scalar();
    require_column_name(windows, name, "a window's name");
    const Eigen::VectorXd w = windows.vector(name, 2);
    if (!w.allFinite() || w(0) < 0 || w(1) <= w(0) || w(1) > s.duration)
      windows.fail(name, "[" + number_text(w(0)) + ", " + number_text(w(1)) + "] must satisfy 0 <= start < end <= duration " +
                             number_text(s.duration));
    o.windows.push_back({name, w(0), w(1)});
  }
}

}  // namespace

ManoeuvringExperiment parse_manoeuvring_scenario(const std::string& text, const std::string& source_name) {
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(text, "empty scenario; expected a map with scenario: manoeuvring_target");
  const YamlMap top = reader.map(root, "", {"scenario", "duration", "sample_time", "truth_substeps", "mu", "orbits",
                                            "manoeuvres", "chaser_navigation", "measurement", "estimate", "filters",
                                            "metrics", "plots"});
  ManoeuvringExperiment e;
  e.path = source_name;
  ManoeuvringScenario& s = e.scenario;
  read_sampled_timing(top, s.duration, s.sample_time, s.truth_substeps);
  read_orbits(top, s);
  read_manoeuvres(top, s);
  read_sensors(top, s);
  read_estimate(top, e.options.estimate);
  read_manoeuvre_filters(top, e.filters);
  read_metrics(top, s, e.options);
  e.plots = top.boolean("plots", e.plots);
  return e;
}

}  // namespace hinf::sim
