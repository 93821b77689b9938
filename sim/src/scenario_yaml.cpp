// Parsing only: YAML → Scenario, with the project's one strict YAML reader
// (hinf::YamlReader, common/): unknown and duplicate keys, quoted numbers and bad values
// are Error(InvalidInput) whose message names file:line:col and the key path.
#include "hinf/sim/scenario_yaml.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hinf/common/error.hpp"
#include "hinf/common/input_file.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "scenario_paths.hpp"

namespace hinf::sim {
namespace {

using Keys = std::vector<std::string>;

const Keys kTopLevelKeys{"duration",      "sample_time", "orbit",    "chaser_mass",
                         "truth",         "control",     "process_noise", "measurement",
                         "estimate",      "filters",     "metrics",  "plots"};
const Keys kFilterKeys{"hinf", "published", "ekf", "ekf_no_control", "rekf"};

// The noise types, in the order of NoiseKind, and the keys each one takes.
const Keys kNoiseTypes{"gaussian",  "gauss_markov", "uniform",  "laplace",
                       "student_t", "impulsive",    "sinusoid", "pulse"};
const Keys kNoiseKeys[] = {{"type", "sigma"},
                           {"type", "sigma", "time_constant"},
                           {"type", "sigma"},
                           {"type", "sigma"},
                           {"type", "sigma", "dof"},
                           {"type", "probability", "magnitude"},
                           {"type", "energy", "frequency", "phase", "start", "end"},
                           {"type", "energy", "start", "end"}};
const Keys kAnyNoiseKey{"type", "sigma", "time_constant", "dof", "probability", "magnitude",
                        "energy", "frequency", "phase", "start", "end"};

// A standard deviation enters the filters squared (R, P₀): above this its square and
// the filters' products of it overflow (a 1e100 m noise is no sensor either).
constexpr double kMaxSigma = 1e100;
constexpr const char* kSigmaRule = "must be <= 1e100 (its square enters the filters' covariances)";

// The ℓ₂-bounded window of a sinusoid or a pulse.
void read_window(const YamlMap& n, NoiseComponent& c) {
  n.required("energy", "ℓ₂ energy Σ d(k)² over the window");
  c.energy = n.nonnegative("energy");
  c.start = n.nonnegative("start", 0.0);
  c.end = n.finite("end", -1.0);
  if (n.has("end") && !(c.end > c.start)) n.fail_value("end", c.end, "must be > start");
}

NoiseComponent read_noise_component(const YamlReader& reader, const YAML::Node& node,
                                    const std::string& path) {
  reader.check_map(node, path, kAnyNoiseKey);
  const YamlMap any(reader, node, path);
  any.required("type", "gaussian, gauss_markov, uniform, laplace, student_t, impulsive, sinusoid, pulse");
  const std::string type = any.choice("type", kNoiseTypes);
  const auto index = std::find(kNoiseTypes.begin(), kNoiseTypes.end(), type) - kNoiseTypes.begin();
  const YamlMap n = reader.map(node, path, kNoiseKeys[index]);
  NoiseComponent c;
  c.kind = static_cast<NoiseKind>(index);
  c.sigma = n.nonnegative("sigma", 0.0);
  if (c.sigma > kMaxSigma) n.fail_value("sigma", c.sigma, kSigmaRule);
  switch (c.kind) {
    case NoiseKind::GaussMarkov:
      n.required("time_constant", "s");
      c.time_constant = n.positive("time_constant");
      break;
    case NoiseKind::StudentT:
      n.required("dof", "degrees of freedom, > 2");
      c.dof = n.finite("dof");
      if (!(c.dof > 2.0)) n.fail_value("dof", c.dof, "must be > 2 (finite variance)");
      break;
    case NoiseKind::Impulsive:
      c.probability = n.nonnegative("probability", 0.0);
      if (c.probability > 1.0) n.fail_value("probability", c.probability, "must be in [0, 1]");
      c.magnitude = n.nonnegative("magnitude", 0.0);
      break;
    case NoiseKind::Sinusoid:
      c.frequency_hz = n.positive("frequency", 1.0);
      c.phase = n.finite("phase", 0.0);
      read_window(n, c);
      break;
    case NoiseKind::Pulse: read_window(n, c); break;
    default: break;
  }
  return c;
}

// A noise channel: one component (a map) or a list of components (summed).
std::vector<NoiseComponent> read_noise(const YamlMap& parent, const std::string& key) {
  std::vector<NoiseComponent> out;
  if (!parent.has(key)) return out;
  for (const auto& [node, path] : parent.reader().one_or_list(parent.get(key), parent.path_of(key)))
    out.push_back(read_noise_component(parent.reader(), node, path));
  return out;
}

// duration (required, a whole number of sample times), sample_time, chaser_mass, plots.
void read_timing(const YamlMap& top, Scenario& s) {
  top.required("duration", "s");
  s.duration = top.positive("duration");
  s.sample_time = top.positive("sample_time", s.sample_time);
  const std::string problem = timing_problem(s.duration, s.sample_time);
  if (!problem.empty()) top.fail_value("duration", s.duration, problem);
  s.chaser_mass = top.positive("chaser_mass", s.chaser_mass);
  s.plots = top.boolean("plots", s.plots);
}

void read_orbit(const YamlMap& top, Scenario& s) {
  if (!top.has("orbit")) return;
  const YamlMap o = top.map("orbit", {"orbital_rate", "mu"});
  s.orbital_rate = o.positive("orbital_rate", s.orbital_rate);
  s.mu = o.positive("mu", s.mu);
}

void read_truth(const YamlMap& top, Scenario& s) {
  top.required("truth", "needs initial_state");
  const YamlMap t = top.map("truth", {"delta", "initial_state", "integrator_substeps"});
  s.truth_delta = t.finite("delta", 0.0);
  if (!(s.truth_delta > -1.0)) t.fail_value("delta", s.truth_delta, "must be > -1 (ω = ω₀(1+δ) > 0)");
  s.initial_state = t.vector("initial_state", 6);
  s.integrator_substeps = t.integer("integrator_substeps", s.integrator_substeps);
  if (s.integrator_substeps < 1 || s.integrator_substeps > 100000)
    t.fail_value("integrator_substeps", s.integrator_substeps, "must be an integer in [1, 100000]");
}

// law: none | state_feedback (default; needs K, 3x6), on: truth (default) | estimate.
void read_control(const YamlMap& top, Scenario& s) {
  if (!top.has("control")) return;
  const YamlMap c = top.map("control", {"law", "on", "K"});
  if (c.choice("law", {"none", "state_feedback"}, "state_feedback") == "none") {
    s.control_law = ControlLaw::None;
    if (c.has("K") || c.has("on")) c.fail("law", "is 'none': remove 'K' and 'on'");
    return;
  }
  s.control_law = ControlLaw::StateFeedback;
  c.required("K", "3x6 gain, u = K x");
  s.K = c.matrix("K", 3, 6);
  s.control_input = c.choice("on", {"truth", "estimate"}, "truth") == "truth" ? ControlInput::Truth
                                                                              : ControlInput::Estimate;
}

void read_measurement(const YamlMap& top, Scenario& s) {
  if (!top.has("measurement")) return;
  const YamlMap m = top.map("measurement", {"C_bl", "range", "azimuth", "elevation"});
  if (m.has("C_bl")) {
    s.C_bl = m.matrix("C_bl", 3, 3);
    const double orth = (s.C_bl * s.C_bl.transpose() - Matrix::Identity(3, 3)).norm();
    if (orth > 1e-9 || s.C_bl.determinant() < 0)
      m.fail("C_bl", "must be a rotation matrix (orthonormal, det +1); ‖C Cᵀ − I‖ = " + number_text(orth));
  }
  s.range_noise = read_noise(m, "range");
  s.azimuth_noise = read_noise(m, "azimuth");
  s.elevation_noise = read_noise(m, "elevation");
}

void read_estimate(const YamlMap& top, Scenario& s) {
  s.initial_estimate << 630, 520, 1000, 0, 0, 0;  // docs/maths.md §9.8
  s.initial_sigma << 50, 50, 50, 0.1, 0.1, 0.1;
  if (!top.has("estimate")) return;
  const YamlMap e = top.map("estimate", {"initial", "sigma", "divergence_limit"});
  if (e.has("initial")) s.initial_estimate = e.vector("initial", 6);
  if (e.has("sigma")) {
    s.initial_sigma = e.vector("sigma", 6);
    const YAML::Node sigma = e.get("sigma");
    for (int i = 0; i < 6; ++i)
      if (!(s.initial_sigma(i) > 0) || s.initial_sigma(i) > kMaxSigma)
        e.reader().fail(sigma[i], e.path_of("sigma") + " entry " + std::to_string(i + 1) + " = " +
                                      number_text(s.initial_sigma(i)) + ": must be > 0 and " + kSigmaRule);
  }
  s.divergence_limit_m = e.positive("divergence_limit", s.divergence_limit_m);
}

// An LTI filter's gains: exactly one of a gains file or a synthesis config.
LtiGainsSource read_lti(const YamlMap& filters, const std::string& key, const std::string& scenario_path) {
  const YamlMap n = filters.map(key, {"gains", "synthesize"});
  if (n.has("gains") == n.has("synthesize"))
    n.reader().fail(n.node(), n.path() + ": needs exactly one of 'gains' (a gains file) or "
                                         "'synthesize' (a synthesis config)");
  LtiGainsSource source;
  if (n.has("gains")) source.gains_path = resolve_scenario_file(n, "gains", scenario_path);
  else source.synthesize_path = resolve_scenario_file(n, "synthesize", scenario_path);
  return source;
}

void read_filters(const YamlMap& top, Scenario& s) {
  top.required("filters", "any of hinf, published, ekf, ekf_no_control, rekf");
  const YamlMap f = top.map("filters", kFilterKeys, EmptyMap::Allowed);
  if (f.has("hinf")) s.filters.hinf = read_lti(f, "hinf", s.path);
  if (f.has("published")) s.filters.published = read_lti(f, "published", s.path);
  for (const char* key : {"ekf", "ekf_no_control"})  // no settings: `ekf: {}`
    if (f.has(key)) f.map(key, {}, EmptyMap::Allowed);
  s.filters.ekf = f.has("ekf");
  s.filters.ekf_no_control = f.has("ekf_no_control");
  if (f.has("rekf")) {
    const YamlMap r = f.map("rekf", {"gamma", "delta_bar"}, EmptyMap::Allowed);
    RekfSettings rekf;
    if (r.has("gamma")) rekf.gamma = r.positive("gamma");
    rekf.delta_bar = r.nonnegative("delta_bar", rekf.delta_bar);
    s.filters.rekf = rekf;
  }
  const FilterSelection& sel = s.filters;
  if (!sel.hinf && !sel.published && !sel.ekf && !sel.ekf_no_control && !sel.rekf)
    f.reader().fail(f.node(), "filters: selects no filter (give any of hinf, published, ekf, "
                              "ekf_no_control, rekf)");
}

// Thrust from the `hinf` estimate needs that filter.
void check_control_input(const YamlMap& top, const Scenario& s) {
  if (s.control_law != ControlLaw::StateFeedback || s.control_input != ControlInput::Estimate ||
      s.filters.hinf)
    return;
  const YAML::Node control = top.get("control");
  top.reader().fail(control["on"], "control.on = 'estimate': needs the 'hinf' filter (the thrust "
                                   "uses its estimate)");
}

void read_metrics(const YamlMap& top, Scenario& s) {
  if (!top.has("metrics")) return;
  const YamlMap m = top.map("metrics", {"steady_state_start", "converge_threshold", "converge_window"});
  const std::string duration = number_text(s.duration);
  if (m.has("steady_state_start")) {
    s.steady_state_start = m.nonnegative("steady_state_start");
    if (*s.steady_state_start > s.duration)
      m.fail_value("steady_state_start", *s.steady_state_start, "beyond the duration " + duration);
  }
  s.converge_threshold_m = m.positive("converge_threshold", s.converge_threshold_m);
  s.converge_window_s = m.nonnegative("converge_window", s.converge_window_s);
  if (s.converge_window_s > s.duration)
    m.fail_value("converge_window", s.converge_window_s, "longer than the duration " + duration);
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::string& source_name) {
  const YamlReader reader(source_name);
  const YAML::Node root =
      reader.load(text, "empty scenario; expected a map with duration, truth and filters");
  const YamlMap top = reader.map(root, "", kTopLevelKeys);
  Scenario s;
  s.path = source_name;
  read_timing(top, s);
  read_orbit(top, s);
  read_truth(top, s);
  read_control(top, s);
  s.process_noise = read_noise(top, "process_noise");
  read_measurement(top, s);
  read_estimate(top, s);
  read_filters(top, s);
  check_control_input(top, s);
  read_metrics(top, s);
  return s;
}

Scenario load_scenario(const std::string& path) {
  return parse_scenario(read_input_file(path, "scenario", kMaxScenarioBytes), path);
}

}  // namespace hinf::sim
