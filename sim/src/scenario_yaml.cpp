// Parsing only: YAML → Scenario, with strict keys and value checks.
#include "hinf/sim/scenario_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>

namespace hinf::sim {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string fmt(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

// A view of one YAML mapping with its key path, used to read keys strictly.
class Node {
 public:
  Node(YAML::Node node, std::string path, const std::string* source)
      : node_(std::move(node)), path_(std::move(path)), source_(source) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw ScenarioError(*source_ + ": " + join(key) + ": " + what);
  }
  std::string join(const std::string& key) const {
    if (key.empty()) return path_.empty() ? "(top level)" : path_;
    return path_.empty() ? key : path_ + "." + key;
  }

  // Every key must be one of `allowed`.
  void require_map(std::initializer_list<const char*> allowed) const {
    if (!node_.IsMap()) fail("", "must be a mapping");
    for (const auto& kv : node_) {
      const std::string key = kv.first.as<std::string>();
      bool ok = false;
      std::string best;
      std::size_t best_d = 1000;
      for (const char* a : allowed) {
        if (key == a) ok = true;
        const std::size_t d = edit_distance(key, a);
        if (d < best_d) best_d = d, best = a;
      }
      if (!ok) {
        std::string msg = "unknown key";
        if (best_d <= 3) msg += "; did you mean '" + join(best) + "'?";
        else {
          msg += "; allowed here:";
          for (const char* a : allowed) msg += std::string(" ") + a;
        }
        fail(key, msg);
      }
    }
  }
  bool has(const char* key) const { return node_[key].IsDefined() && !node_[key].IsNull(); }
  Node child(const char* key) const { return Node(node_[key], join(key), source_); }
  const YAML::Node& yaml() const { return node_; }
  const std::string& path() const { return path_; }
  const std::string& source() const { return *source_; }

  double number(const char* key) const {
    const YAML::Node v = node_[key];
    if (!v.IsScalar()) fail(key, "must be a number");
    double d;
    try {
      d = v.as<double>();
    } catch (const YAML::Exception&) {
      fail(key, "must be a number, got '" + v.as<std::string>() + "'");
    }
    if (!std::isfinite(d)) fail(key, "must be finite, got " + v.as<std::string>());
    return d;
  }
  double number(const char* key, double fallback) const { return has(key) ? number(key) : fallback; }
  double positive(const char* key, double fallback) const {
    const double d = number(key, fallback);
    if (!(d > 0)) fail(key, "= " + fmt(d) + ": must be > 0");
    return d;
  }
  double nonnegative(const char* key, double fallback) const {
    const double d = number(key, fallback);
    if (d < 0) fail(key, "= " + fmt(d) + ": must be >= 0");
    return d;
  }
  std::string string(const char* key) const {
    const YAML::Node v = node_[key];
    if (!v.IsScalar()) fail(key, "must be a string");
    return v.as<std::string>();
  }
  bool boolean(const char* key, bool fallback) const {
    if (!has(key)) return fallback;
    try {
      return node_[key].as<bool>();
    } catch (const YAML::Exception&) {
      fail(key, "must be true or false");
    }
  }
  std::vector<double> vector(const char* key, std::size_t size) const {
    const YAML::Node v = node_[key];
    if (!v.IsSequence() || v.size() != size)
      fail(key, "must be a list of " + std::to_string(size) + " numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < size; ++i) {
      double d;
      try {
        d = v[i].as<double>();
      } catch (const YAML::Exception&) {
        fail(key, "entry " + std::to_string(i) + " is not a number");
      }
      if (!std::isfinite(d)) fail(key, "entry " + std::to_string(i) + " is not finite");
      out.push_back(d);
    }
    return out;
  }
  // Nested row list [[..], ..] or {diag: [..]}.
  Matrix matrix(const char* key, int rows, int cols) const {
    const YAML::Node v = node_[key];
    const std::string shape = std::to_string(rows) + "x" + std::to_string(cols);
    if (v.IsMap()) {
      Node d(v, join(key), source_);
      d.require_map({"diag"});
      if (rows != cols) fail(key, "must be " + shape + " (not square: {diag: ...} not allowed)");
      const std::vector<double> diag = d.vector("diag", rows);
      Matrix M = Matrix::Zero(rows, cols);
      for (int i = 0; i < rows; ++i) M(i, i) = diag[i];
      return M;
    }
    if (!v.IsSequence() || static_cast<int>(v.size()) != rows)
      fail(key, "must be a " + shape + " matrix (a list of " + std::to_string(rows) + " rows)");
    Matrix M(rows, cols);
    for (int i = 0; i < rows; ++i) {
      if (!v[i].IsSequence() || static_cast<int>(v[i].size()) != cols)
        fail(key, "row " + std::to_string(i) + " must have " + std::to_string(cols) + " entries (matrix " + shape + ")");
      for (int j = 0; j < cols; ++j) {
        try {
          M(i, j) = v[i][j].as<double>();
        } catch (const YAML::Exception&) {
          fail(key, "entry (" + std::to_string(i) + ", " + std::to_string(j) + ") is not a number");
        }
        if (!std::isfinite(M(i, j)))
          fail(key, "entry (" + std::to_string(i) + ", " + std::to_string(j) + ") is not finite");
      }
    }
    return M;
  }

 private:
  YAML::Node node_;
  std::string path_;
  const std::string* source_;
};

NoiseComponent parse_noise_component(const Node& n) {
  if (!n.yaml().IsMap()) n.fail("", "must be a mapping with a 'type' key");
  if (!n.has("type")) n.fail("type", "missing (gaussian, gauss_markov, uniform, laplace, student_t, impulsive, sinusoid, pulse)");
  const std::string type = n.string("type");
  NoiseComponent c;
  if (type == "gaussian" || type == "uniform" || type == "laplace") {
    n.require_map({"type", "sigma"});
    c.kind = type == "gaussian" ? NoiseKind::Gaussian : type == "uniform" ? NoiseKind::Uniform : NoiseKind::Laplace;
    c.sigma = n.nonnegative("sigma", 0.0);
  } else if (type == "gauss_markov") {
    n.require_map({"type", "sigma", "time_constant"});
    c.kind = NoiseKind::GaussMarkov;
    c.sigma = n.nonnegative("sigma", 0.0);
    if (!n.has("time_constant")) n.fail("time_constant", "missing (s)");
    c.time_constant = n.positive("time_constant", 0.0);
  } else if (type == "student_t") {
    n.require_map({"type", "sigma", "dof"});
    c.kind = NoiseKind::StudentT;
    c.sigma = n.nonnegative("sigma", 0.0);
    if (!n.has("dof")) n.fail("dof", "missing (degrees of freedom, > 2)");
    c.dof = n.number("dof");
    if (!(c.dof > 2.0)) n.fail("dof", "= " + fmt(c.dof) + ": must be > 2 (finite variance)");
  } else if (type == "impulsive") {
    n.require_map({"type", "probability", "magnitude"});
    c.kind = NoiseKind::Impulsive;
    c.probability = n.nonnegative("probability", 0.0);
    if (c.probability > 1.0) n.fail("probability", "= " + fmt(c.probability) + ": must be in [0, 1]");
    c.magnitude = n.nonnegative("magnitude", 0.0);
  } else if (type == "sinusoid" || type == "pulse") {
    if (type == "sinusoid") {
      n.require_map({"type", "energy", "frequency", "phase", "start", "end"});
      c.kind = NoiseKind::Sinusoid;
      c.frequency_hz = n.positive("frequency", 1.0);
      c.phase = n.number("phase", 0.0);
    } else {
      n.require_map({"type", "energy", "start", "end"});
      c.kind = NoiseKind::Pulse;
    }
    if (!n.has("energy")) n.fail("energy", "missing (ℓ₂ energy Σ d(k)² over the window)");
    c.energy = n.nonnegative("energy", 0.0);
    c.start = n.nonnegative("start", 0.0);
    c.end = n.has("end") ? n.number("end") : -1.0;
    if (n.has("end") && !(c.end > c.start)) n.fail("end", "= " + fmt(c.end) + ": must be > start");
  } else {
    n.fail("type", "unknown noise type '" + type +
                       "' (gaussian, gauss_markov, uniform, laplace, student_t, impulsive, sinusoid, pulse)");
  }
  return c;
}

// A noise channel: one component (a mapping) or a list of components (summed).
std::vector<NoiseComponent> parse_noise(const Node& parent, const char* key) {
  if (!parent.has(key)) return {};
  const Node n = parent.child(key);
  std::vector<NoiseComponent> out;
  if (n.yaml().IsSequence()) {
    for (std::size_t i = 0; i < n.yaml().size(); ++i)
      out.push_back(parse_noise_component(Node(n.yaml()[i], n.path() + "[" + std::to_string(i) + "]", &n.source())));
  } else {
    out.push_back(parse_noise_component(n));
  }
  return out;
}

std::string resolve(const Node& n, const char* key, const std::string& scenario_path) {
  const std::string value = n.string(key);
  std::filesystem::path p(value);
  if (p.is_relative()) p = std::filesystem::path(scenario_path).parent_path() / p;
  if (!std::filesystem::exists(p)) n.fail(key, "file '" + p.string() + "' does not exist (relative paths resolve against the scenario file's directory)");
  return p.lexically_normal().string();
}

LtiGainsSource parse_lti(const Node& n, const std::string& scenario_path) {
  n.require_map({"gains", "synthesize"});
  if (n.has("gains") == n.has("synthesize")) n.fail("", "needs exactly one of 'gains' (a gains file) or 'synthesize' (a synthesis config)");
  LtiGainsSource s;
  if (n.has("gains")) s.gains_path = resolve(n, "gains", scenario_path);
  else s.synthesize_path = resolve(n, "synthesize", scenario_path);
  return s;
}

void require_empty_or_map(const Node& n) {
  if (n.yaml().IsNull()) return;
  n.require_map({});
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::string& source_name) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ScenarioError(source_name + ": not valid YAML: " + e.what());
  }
  Scenario s;
  s.path = source_name;
  const Node top(root, "", &s.path);
  top.require_map({"duration", "sample_time", "orbit", "chaser_mass", "truth", "control", "process_noise",
                   "measurement", "estimate", "filters", "metrics", "plots"});

  if (!top.has("duration")) top.fail("duration", "missing (s)");
  s.duration = top.positive("duration", 0);
  s.sample_time = top.positive("sample_time", s.sample_time);
  const double ratio = s.duration / s.sample_time;
  if (std::fabs(ratio - std::round(ratio)) > 1e-6 * std::max(1.0, ratio))
    top.fail("duration", "= " + fmt(s.duration) + ": must be a whole number of sample times (" + fmt(s.sample_time) + " s)");
  s.chaser_mass = top.positive("chaser_mass", s.chaser_mass);
  s.plots = top.boolean("plots", true);

  if (top.has("orbit")) {
    const Node o = top.child("orbit");
    o.require_map({"orbital_rate", "mu"});
    s.orbital_rate = o.positive("orbital_rate", s.orbital_rate);
    s.mu = o.positive("mu", s.mu);
  }

  if (!top.has("truth")) top.fail("truth", "missing (needs initial_state)");
  {
    const Node t = top.child("truth");
    t.require_map({"delta", "initial_state", "integrator_substeps"});
    s.truth_delta = t.number("delta", 0.0);
    if (!(s.truth_delta > -1.0)) t.fail("delta", "= " + fmt(s.truth_delta) + ": must be > -1 (ω = ω₀(1+δ) > 0)");
    const auto x0 = t.vector("initial_state", 6);
    for (int i = 0; i < 6; ++i) s.initial_state(i) = x0[i];
    const double sub = t.number("integrator_substeps", 10);
    if (sub < 1 || sub != std::floor(sub) || sub > 100000) t.fail("integrator_substeps", "= " + fmt(sub) + ": must be an integer in [1, 100000]");
    s.integrator_substeps = static_cast<int>(sub);
  }

  if (top.has("control")) {
    const Node c = top.child("control");
    c.require_map({"law", "on", "K"});
    const std::string law = c.has("law") ? c.string("law") : "state_feedback";
    if (law == "none") {
      s.control_law = ControlLaw::None;
      if (c.has("K") || c.has("on")) c.fail("law", "is 'none': remove 'K' and 'on'");
    } else if (law == "state_feedback") {
      s.control_law = ControlLaw::StateFeedback;
      if (!c.has("K")) c.fail("K", "missing (3x6 gain, u = K x)");
      s.K = c.matrix("K", 3, 6);
      const std::string on = c.has("on") ? c.string("on") : "truth";
      if (on == "truth") s.control_input = ControlInput::Truth;
      else if (on == "estimate") s.control_input = ControlInput::Estimate;
      else c.fail("on", "= '" + on + "': must be 'truth' or 'estimate'");
    } else {
      c.fail("law", "= '" + law + "': must be 'none' or 'state_feedback'");
    }
  }

  s.process_noise = parse_noise(top, "process_noise");

  if (top.has("measurement")) {
    const Node m = top.child("measurement");
    m.require_map({"C_bl", "range", "azimuth", "elevation"});
    if (m.has("C_bl")) {
      s.C_bl = m.matrix("C_bl", 3, 3);
      const double orth = (s.C_bl * s.C_bl.transpose() - Matrix::Identity(3, 3)).norm();
      if (orth > 1e-9 || s.C_bl.determinant() < 0)
        m.fail("C_bl", "must be a rotation matrix (orthonormal, det +1); ‖C Cᵀ − I‖ = " + fmt(orth));
    }
    s.range_noise = parse_noise(m, "range");
    s.azimuth_noise = parse_noise(m, "azimuth");
    s.elevation_noise = parse_noise(m, "elevation");
  }

  s.initial_estimate << 630, 520, 1000, 0, 0, 0;  // SPEC §3
  s.initial_sigma << 50, 50, 50, 0.1, 0.1, 0.1;
  if (top.has("estimate")) {
    const Node e = top.child("estimate");
    e.require_map({"initial", "sigma", "divergence_limit"});
    if (e.has("initial")) {
      const auto v = e.vector("initial", 6);
      for (int i = 0; i < 6; ++i) s.initial_estimate(i) = v[i];
    }
    if (e.has("sigma")) {
      const auto v = e.vector("sigma", 6);
      for (int i = 0; i < 6; ++i) {
        if (!(v[i] > 0)) e.fail("sigma", "entry " + std::to_string(i) + " = " + fmt(v[i]) + ": must be > 0");
        s.initial_sigma(i) = v[i];
      }
    }
    s.divergence_limit_m = e.positive("divergence_limit", s.divergence_limit_m);
  }

  if (!top.has("filters")) top.fail("filters", "missing (any of hinf, published, ekf, ekf_no_control, rekf)");
  {
    const Node f = top.child("filters");
    f.require_map({"hinf", "published", "ekf", "ekf_no_control", "rekf"});
    if (f.yaml()["hinf"].IsDefined()) s.filters.hinf = parse_lti(f.child("hinf"), s.path);
    if (f.yaml()["published"].IsDefined()) s.filters.published = parse_lti(f.child("published"), s.path);
    if (f.yaml()["ekf"].IsDefined()) require_empty_or_map(f.child("ekf")), s.filters.ekf = true;
    if (f.yaml()["ekf_no_control"].IsDefined()) require_empty_or_map(f.child("ekf_no_control")), s.filters.ekf_no_control = true;
    if (f.yaml()["rekf"].IsDefined()) {
      const Node r = f.child("rekf");
      RekfSettings rs;
      if (!r.yaml().IsNull()) {
        r.require_map({"gamma", "delta_bar"});
        if (r.has("gamma")) rs.gamma = r.positive("gamma", 1.0);
        rs.delta_bar = r.nonnegative("delta_bar", rs.delta_bar);
      }
      s.filters.rekf = rs;
    }
    if (!s.filters.hinf && !s.filters.published && !s.filters.ekf && !s.filters.ekf_no_control && !s.filters.rekf)
      f.fail("", "selects no filter");
  }
  if (s.control_law == ControlLaw::StateFeedback && s.control_input == ControlInput::Estimate && !s.filters.hinf)
    top.fail("control.on", "= 'estimate' needs the 'hinf' filter (the thrust uses its estimate)");

  if (top.has("metrics")) {
    const Node m = top.child("metrics");
    m.require_map({"steady_state_start", "converge_threshold", "converge_window"});
    if (m.has("steady_state_start")) {
      const double st = m.nonnegative("steady_state_start", 0);
      if (st > s.duration) m.fail("steady_state_start", "= " + fmt(st) + ": beyond the duration " + fmt(s.duration));
      s.steady_state_start = st;
    }
    s.converge_threshold_m = m.positive("converge_threshold", s.converge_threshold_m);
    if (m.has("converge_window")) {
      const double w = m.nonnegative("converge_window", 0);
      if (w > s.duration) m.fail("converge_window", "= " + fmt(w) + ": longer than the duration " + fmt(s.duration));
      s.converge_window_s = w;
    }
  }
  return s;
}

Scenario load_scenario(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot read the scenario file");
  std::ostringstream os;
  os << in.rdbuf();
  return parse_scenario(os.str(), path);
}

}  // namespace hinf::sim
