// Parsing only: YAML → GyrolessExperiment (gyroless_scenario_yaml.hpp), with the project's one
// strict YAML reader.
#include "hinf/sim/gyroless_scenario_yaml.hpp"

#include <cmath>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "scenario_fields.hpp"

namespace hinf::sim {

namespace {

using models::kRadiansPerDegree;

void read_timing(const YamlMap& top, GyrolessScenario& s) {
  read_sampled_timing(top, s.duration, s.sample_time, s.truth_substeps);
}

// A unit quaternion [q1, q2, q3, q4] (scalar last), normalised; zero is refused.
models::Quaternion read_quaternion(const YamlMap& m, const char* key, const models::Quaternion& fallback) {
  if (!m.has(key)) return fallback;
  const Eigen::VectorXd q = m.vector(key, 4);
  if (!q.allFinite() || q.norm() == 0) m.fail(key, "must be a finite, non-zero quaternion [q1, q2, q3, q4]");
  return q.normalized();
}

void read_body(const YamlMap& top, GyrolessScenario& s) {
  if (top.has("orbit")) {
    const YamlMap o = top.map("orbit", {"orbital_rate_deg_s"});
    s.orbital_rate = o.positive("orbital_rate_deg_s", s.orbital_rate / kRadiansPerDegree) * kRadiansPerDegree;
  }
  if (top.has("frame_model")) top.choice("frame_model", {"orbit_as_inertial"});
  if (top.has("spacecraft")) {
    const YamlMap c = top.map("spacecraft", {"inertia", "wheel_momentum"});
    if (c.has("inertia")) {
      const Eigen::MatrixXd J = c.matrix("inertia", 3, 3);
      if (!J.allFinite() || (J - J.transpose()).cwiseAbs().maxCoeff() > 1e-12 * J.norm() ||
          Eigen::LLT<Eigen::Matrix3d>(J).info() != Eigen::Success)
        c.fail("inertia", "must be symmetric positive definite");
      s.inertia = J;
    }
    s.wheel_momentum = scenario_vector3(c, "wheel_momentum", s.wheel_momentum);
  }
  if (top.has("disturbance")) {
    const YamlMap d = top.map("disturbance", {"amplitude", "harmonic", "sign"});
    s.torque_amplitude = scenario_vector3(d, "amplitude", s.torque_amplitude);
    if (s.torque_amplitude.minCoeff() < 0) d.fail("amplitude", "every entry must be >= 0 (the sign is `sign`)");
    s.torque_harmonic = scenario_vector3(d, "harmonic", s.torque_harmonic);
    if (s.torque_harmonic.minCoeff() < 0) d.fail("harmonic", "every entry must be >= 0");
    s.torque_sign = scenario_vector3(d, "sign", s.torque_sign);
    for (int i = 0; i < 3; ++i)
      if (std::abs(s.torque_sign(i)) != 1) d.fail("sign", "each entry must be 1 or -1");
  }
  if (top.has("truth")) {
    const YamlMap t = top.map("truth", {"q0", "w0"});
    s.q0 = read_quaternion(t, "q0", s.q0);
    s.w0 = scenario_vector3(t, "w0", s.w0);
  }
}

void read_star_tracker(const YamlMap& top, GyrolessScenario& s) {
  if (!top.has("star_tracker")) return;
  const YamlMap m = top.map("star_tracker", {"reference_vectors", "noise_variance"});
  if (m.has("reference_vectors")) {
    const Eigen::MatrixXd r = m.matrix("reference_vectors", 2, 3, MatrixForms::RowsOnly);
    for (int i = 0; i < 2; ++i) {
      if (!r.row(i).allFinite() || r.row(i).norm() == 0)
        m.fail("reference_vectors", "row " + std::to_string(i + 1) + ": must be a finite, non-zero direction");
      s.reference_vectors[static_cast<std::size_t>(i)] = r.row(i).transpose().normalized();
    }
    if (s.reference_vectors[0].cross(s.reference_vectors[1]).norm() < 1e-6)
      m.fail("reference_vectors", "the two directions are parallel: the attitude is not observable");
  }
  s.star_tracker_variance = m.positive("noise_variance", s.star_tracker_variance);
}

void read_estimate(const YamlMap& top, GyrolessInitialEstimate& e) {
  if (!top.has("estimate")) return;
  const YamlMap m =
      top.map("estimate", {"q0", "w0", "torque0", "sigma", "prediction_substeps", "sample_initial_error"});
  e.q0 = read_quaternion(m, "q0", e.q0);
  e.w0 = scenario_vector3(m, "w0", e.w0);
  e.torque0 = scenario_vector3(m, "torque0", e.torque0);
  if (m.has("sigma")) {
    const YamlMap s = m.map("sigma", {"attitude", "rate", "torque"});
    e.sigma_attitude = s.positive("attitude", e.sigma_attitude);
    e.sigma_rate = s.positive("rate", e.sigma_rate);
    e.sigma_torque = s.positive("torque", e.sigma_torque);
  }
  e.prediction_substeps = m.integer("prediction_substeps", e.prediction_substeps);
  if (e.prediction_substeps < 1 || e.prediction_substeps > 1000) m.fail("prediction_substeps", "must be in 1…1000");
  e.sample = m.boolean("sample_initial_error", e.sample);
}

void read_strong_tracking(const YamlMap& f, runtime::StrongTrackingSettings<9>& st) {
  st.forgetting = f.positive("forgetting", st.forgetting);
  if (st.forgetting > 1) f.fail_value("forgetting", st.forgetting, "must be in (0, 1]");
  st.weakening = f.positive("weakening", st.weakening);
  if (st.weakening < 1) f.fail_value("weakening", st.weakening, "must be >= 1");
  if (f.has("alpha")) {
    const Eigen::VectorXd a = f.vector("alpha", 9);
    for (int i = 0; i < 9; ++i)
      if (!(a(i) >= 1) || !std::isfinite(a(i)))
        f.fail("alpha", "entry " + std::to_string(i + 1) + " is " + number_text(a(i)) + "; every alpha must be >= 1");
    st.alpha = a;
  }
  if (f.has("fading_form"))
    st.form = f.choice("fading_form", {"symmetric", "literal_symmetrised"}) == "symmetric"
                  ? runtime::FadingForm::Symmetric
                  : runtime::FadingForm::LiteralSymmetrised;
  st.lambda_max = f.positive("lambda_max", st.lambda_max);
  if (st.lambda_max < 1) f.fail_value("lambda_max", st.lambda_max, "must be >= 1");
}

void read_adaptive(const YamlMap& f, runtime::AdaptiveQSettings& a) {
  a.initial = f.positive("Q_initial", a.initial);
  a.scale = f.positive("scale", a.scale);
  a.epsilon = f.nonnegative("epsilon", a.epsilon);
  a.window = f.integer("window", a.window);
  if (a.window < 1 || a.window > 100000) f.fail("window", "must be in 1…100000 steps");
  if (f.has("law"))
    a.law = f.choice("law", {"diag", "outer"}) == "outer" ? runtime::AdaptiveQLaw::Outer : runtime::AdaptiveQLaw::Diagonal;
  a.floor = f.nonnegative("floor", a.floor);
}

GyrolessFilterSettings read_gyroless_filter(const YamlMap& filters, const std::string& name) {
  require_column_name(filters, name, "a filter's name");
  const YamlMap f = filters.map(name, {"type", "Q", "forgetting", "weakening", "alpha", "fading_form", "lambda_max",
                                       "Q_initial", "scale", "epsilon", "window", "law", "floor"},
                                EmptyMap::Allowed);
  GyrolessFilterSettings s;
  s.name = name;
  std::string type = name == "aekf" || name == "astekf" || name == "aaekf" ? name : "";
  if (f.has("type")) type = f.choice("type", {"aekf", "astekf", "aaekf"});
  if (type.empty()) f.reader().fail(f.node(), "filters." + name + ": needs type: aekf, astekf or aaekf");
  s.kind = type == "astekf" ? GyrolessFilterKind::Astekf : type == "aaekf" ? GyrolessFilterKind::Aaekf : GyrolessFilterKind::Aekf;
  const std::vector<std::string> st_keys{"forgetting", "weakening", "alpha", "fading_form", "lambda_max"};
  const std::vector<std::string> aa_keys{"Q_initial", "scale", "epsilon", "window", "law", "floor"};
  for (const auto& k : st_keys)
    if (f.has(k) && s.kind != GyrolessFilterKind::Astekf) f.fail(k, "only with type: astekf");
  for (const auto& k : aa_keys)
    if (f.has(k) && s.kind != GyrolessFilterKind::Aaekf) f.fail(k, "only with type: aaekf");
  if (f.has("Q") && s.kind == GyrolessFilterKind::Aaekf) f.fail("Q", "type: aaekf adapts Q; give Q_initial");
  s.Q = f.positive("Q", s.Q);
  if (s.kind == GyrolessFilterKind::Astekf) read_strong_tracking(f, s.strong_tracking);
  if (s.kind == GyrolessFilterKind::Aaekf) read_adaptive(f, s.adaptive);
  return s;
}

void read_gyroless_filters(const YamlMap& top, std::vector<GyrolessFilterSettings>& out) {
  read_named_filters(top, static_cast<std::size_t>(kMaxGyrolessFilters), "aekf, astekf, aaekf, …",
                     [&](const YamlMap& filters, const std::string& name) { out.push_back(read_gyroless_filter(filters, name)); });
}

// sweep: {<filter>: [Q, …]}: a copy of the (aekf or astekf) filter per Q.
void read_sweep(const YamlMap& top, std::vector<GyrolessFilterSettings>& filters) {
  if (!top.has("sweep")) return;
  const YAML::Node node = top.get("sweep");
  if (!node.IsMap()) top.reader().fail(node, "sweep: must be a map of filter names to lists of Q");
  const YamlMap sweep(top.reader(), node, top.path_of("sweep"));
  const std::size_t named = filters.size();
  for (const auto& kv : node) {
    const std::string name = kv.first.IsScalar() ? kv.first.Scalar() : "";
    std::size_t base = named;
    for (std::size_t f = 0; f < named; ++f)
      if (filters[f].name == name) base = f;
    if (base == named) sweep.fail(name, "names no filter of `filters`");
    if (filters[base].kind == GyrolessFilterKind::Aaekf) sweep.fail(name, "type: aaekf adapts Q; only aekf and astekf sweep");
    const Eigen::VectorXd q = sweep.vector(name);
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      if (!(q(i) > 0) || !std::isfinite(q(i)))
        sweep.fail(name, "entry " + std::to_string(i + 1) + " is " + number_text(q(i)) + "; every Q must be > 0");
      GyrolessFilterSettings s = filters[base];
      s.Q = q(i);
      s.name = name + "_q" + number_text(q(i));
      s.swept_from = name;
      for (const GyrolessFilterSettings& other : filters)
        if (other.name == s.name) sweep.fail(name, "Q " + number_text(q(i)) + " is given twice (" + s.name + ")");
      filters.push_back(s);
    }
  }
  if (filters.size() > static_cast<std::size_t>(kMaxGyrolessFilters))
    top.reader().fail(node, "sweep: at most " + std::to_string(kMaxGyrolessFilters) + " filters in all, got " +
                                std::to_string(filters.size()));
}

void read_metrics(const YamlMap& top, const GyrolessScenario& s, GyrolessRunOptions& o) {
  o.window_start = std::min(o.window_start, s.duration / 2);
  if (!top.has("metrics")) return;
  const YamlMap m = top.map("metrics", {"steady_state_start"});
  o.window_start = m.nonnegative("steady_state_start", o.window_start);
  if (o.window_start >= s.duration)
    m.fail_value("steady_state_start", o.window_start, "must be before the end, duration " + number_text(s.duration));
}

}  // namespace

GyrolessExperiment parse_gyroless_scenario(const std::string& text, const std::string& source_name) {
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(text, "empty scenario; expected a map with scenario: gyroless_attitude");
  const YamlMap top = reader.map(root, "", {"scenario", "duration", "sample_time", "truth_substeps", "orbit",
                                            "frame_model", "spacecraft", "disturbance", "truth", "star_tracker",
                                            "estimate", "attitude_error", "q_discretisation", "filters", "sweep",
                                            "metrics", "plots"});
  GyrolessExperiment e;
  e.path = source_name;
  GyrolessScenario& s = e.scenario;
  read_timing(top, s);
  read_body(top, s);
  read_star_tracker(top, s);
  read_estimate(top, e.options.estimate);
  if (top.has("attitude_error")) top.choice("attitude_error", {"multiplicative"});
  if (top.has("q_discretisation")) top.choice("q_discretisation", {"first_order"});
  read_gyroless_filters(top, e.filters);
  read_sweep(top, e.filters);
  read_metrics(top, s, e.options);
  e.plots = top.boolean("plots", e.plots);
  return e;
}

}  // namespace hinf::sim
