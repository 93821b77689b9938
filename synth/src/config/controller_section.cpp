// parse_controller_config: `controller:` and `solver:` (controller_config.hpp).
#include "config/sections.hpp"
#include "config/sha256.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/models/tumbling_hold.hpp"
#include "hinf/synth/controller_config.hpp"

namespace hinf::synth {

namespace {

// A matrix of `controller:` with the shape the others fix (rows, cols; −1: free).
Eigen::MatrixXd plant_matrix(const YamlMap& c, const char* key, Eigen::Index rows, Eigen::Index cols) {
  c.required(key, "a matrix of the generalised plant, docs/maths.md (145)");
  if (rows < 0 || cols < 0) return c.matrix(key);
  return c.matrix(key, rows, cols);
}

const std::vector<std::string> kCommonKeys{"time", "sample_time", "strictly_proper", "pole_disk_radius", "robust"};
const std::vector<std::string> kMatrixKeys{"A", "B1", "B2", "C1", "C2", "D11", "D12", "D21"};
const std::vector<std::string> kModelKeys{"model",          "servicer_mass",      "target_rate_deg_s",
                                          "target_accel_deg_s2", "orbit_rate",   "disturbance_sigma",
                                          "measurement_sigma", "include_measurement_noise_channel",
                                          "weights",        "integral_action",    "integral_leak"};

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The generalised plant given as matrices, and its optional robust channel {H, E}.
hinf::GeneralisedPlant read_plant_matrices(const YamlMap& c, ControllerDesign& design) {
  hinf::GeneralisedPlant P;
  P.A = plant_matrix(c, "A", -1, -1);
  const Eigen::Index n = P.A.rows();
  if (P.A.cols() != n) c.fail("A", "must be square, got " + std::to_string(n) + "x" + std::to_string(P.A.cols()));
  P.B1 = plant_matrix(c, "B1", -1, -1);
  P.B2 = plant_matrix(c, "B2", -1, -1);
  P.C1 = plant_matrix(c, "C1", -1, -1);
  P.C2 = plant_matrix(c, "C2", -1, -1);
  for (const auto& [key, M, by_rows] : {std::tuple<const char*, const Eigen::MatrixXd&, bool>{"B1", P.B1, true},
                                        {"B2", P.B2, true}, {"C1", P.C1, false}, {"C2", P.C2, false}}) {
    const Eigen::Index got = by_rows ? M.rows() : M.cols();
    if (got != n)
      c.fail(key, std::string("expected ") + std::to_string(n) + (by_rows ? " rows" : " columns") +
                      " (A is " + std::to_string(n) + "x" + std::to_string(n) + "), got " + std::to_string(got));
  }
  P.D12 = plant_matrix(c, "D12", P.C1.rows(), P.B2.cols());
  P.D21 = plant_matrix(c, "D21", P.C2.rows(), P.B1.cols());
  P.D11 = c.has("D11") ? c.matrix("D11", P.C1.rows(), P.B1.cols()) : Eigen::MatrixXd::Zero(P.C1.rows(), P.B1.cols());
  if (c.has("robust")) {
    const YamlMap r = c.map("robust", {"H", "E"});
    r.required("H", "n x p: where the perturbation p enters the state (docs/maths.md (160))");
    r.required("E", "q x n: the perturbation's input q = E x");
    design.robust = hinf::UncertaintyChannel{r.matrix("H"), r.matrix("E")};
    if (design.robust->H.rows() != n) r.fail("H", "expected " + std::to_string(n) + " rows (A is " + std::to_string(n) + "x" + std::to_string(n) + "), got " + std::to_string(design.robust->H.rows()));
    if (design.robust->E.cols() != n) r.fail("E", "expected " + std::to_string(n) + " columns (A is " + std::to_string(n) + "x" + std::to_string(n) + "), got " + std::to_string(design.robust->E.cols()));
  }
  return P;
}

Eigen::Vector3d degrees_vector(const YamlMap& c, const char* key, const Eigen::Vector3d& fallback_rad) {
  if (!c.has(key)) return fallback_rad;
  const Eigen::VectorXd v = c.vector(key, 3);
  if (!v.allFinite()) c.fail(key, "must be finite");
  return v * hinf::models::kRadiansPerDegree;
}

// Values each finite that the model turns into a non-finite matrix (servicer_mass 4.9e-324:
// B2 = 1/m) are refused naming the model's values, not the internal matrix alone.
void require_finite_model(const YamlMap& c, const hinf::GeneralisedPlant& P, const hinf::models::TumblingHoldModel& m) {
  const std::pair<const char*, const Eigen::MatrixXd*> matrices[] = {
      {"A", &P.A}, {"B1", &P.B1}, {"B2", &P.B2}, {"C1", &P.C1}, {"C2", &P.C2}, {"D11", &P.D11}, {"D12", &P.D12}, {"D21", &P.D21}};
  for (const auto& [name, M] : matrices)
    if (!M->allFinite())
      c.fail("model", std::string("tumbling_hold builds a non-finite ") + name + " (docs/maths.md (159)) from servicer_mass = " +
                          number_text(m.servicer_mass) + ", orbit_rate = " + number_text(m.orbit_rate) +
                          ", disturbance_sigma = " + number_text(m.disturbance_sigma) + ", measurement_sigma = " +
                          number_text(m.measurement_sigma) + " and the weights: their products leave floating-point range");
}

// The physical model `model: tumbling_hold` (docs/maths.md §27, (157)–(160)) with its defaults.
hinf::GeneralisedPlant read_tumbling_hold(const YamlMap& c, ControllerDesign& design) {
  c.choice("model", {"tumbling_hold"});
  hinf::models::TumblingHoldModel m;
  m.servicer_mass = c.positive("servicer_mass", m.servicer_mass);
  m.target_rate = degrees_vector(c, "target_rate_deg_s", m.target_rate);
  m.target_accel = degrees_vector(c, "target_accel_deg_s2", m.target_accel);
  m.orbit_rate = c.nonnegative("orbit_rate", m.orbit_rate);
  m.disturbance_sigma = c.positive("disturbance_sigma", m.disturbance_sigma);
  m.measurement_sigma = c.positive("measurement_sigma", m.measurement_sigma);
  m.measurement_noise_channel = c.boolean("include_measurement_noise_channel", m.measurement_noise_channel);
  if (c.has("weights")) {
    const YamlMap w = c.map("weights", {"position", "velocity", "force", "integral"});
    m.position_weight = w.positive("position", m.position_weight);
    m.velocity_weight = w.nonnegative("velocity", m.velocity_weight);
    m.force_weight = w.positive("force", m.force_weight);
    m.integral_weight = w.positive("integral", m.integral_weight);
  }
  m.integral_action = c.boolean("integral_action", m.integral_action);
  m.integral_leak = c.positive("integral_leak", m.integral_leak);
  for (const char* key : {"integral_leak"})
    if (c.has(key) && !m.integral_action) c.fail(key, "only with integral_action: true");
  if (c.has("weights") && c.get("weights")["integral"] && !m.integral_action)
    c.fail("weights", "weights.integral only with integral_action: true");
  hinf::GeneralisedPlant P = hinf::models::tumbling_hold_plant(m);
  if (c.has("robust")) {
    const YamlMap r = c.map("robust", {"rate_uncertainty_deg_s", "accel_uncertainty_deg_s2", "gravity_gradient"});
    hinf::models::TumblingHoldUncertainty u;
    u.rate = r.nonnegative("rate_uncertainty_deg_s", 0.0) * hinf::models::kRadiansPerDegree;
    u.accel = r.nonnegative("accel_uncertainty_deg_s2", 0.0) * hinf::models::kRadiansPerDegree;
    u.gravity_gradient = r.boolean("gravity_gradient", true);
    design.robust = hinf::models::tumbling_hold_uncertainty(m, u, P.n());
  }
  require_finite_model(c, P, m);
  return P;
}

hinf::GeneralisedPlant read_controller_section(const YamlReader& reader, const YAML::Node& node, ControllerDesign& design) {
  const bool model = node && node.IsMap() && node["model"];
  const YamlMap c = reader.map(node, "controller", joined(kCommonKeys, model ? kModelKeys : kMatrixKeys));
  c.required("time", "continuous or discrete");
  const bool discrete = c.choice("time", {"continuous", "discrete"}) == "discrete";
  double sample_time = 0;
  if (discrete) {
    c.required("sample_time", "the controller's period in discrete time, s");
    sample_time = c.positive("sample_time");
  } else if (c.has("sample_time")) {
    c.fail("sample_time", "only with controller.time: discrete (a continuous-time controller has no period)");
  }
  hinf::GeneralisedPlant P;
  if (model) {  // a continuous physical model, sampled for a discrete design
    P = read_tumbling_hold(c, design);
    if (discrete) {
      if (const std::string problem = hinf::models::held_input_problem(P.A, sample_time); !problem.empty())
        c.fail_value("sample_time", sample_time, problem);
      if (design.robust) design.robust->H = hinf::models::discretise(P.A, sample_time, hinf::models::Discretisation::ZeroOrderHold).Gamma * design.robust->H;
      P = hinf::models::sampled_plant(P, sample_time);
    }
  } else {
    P = read_plant_matrices(c, design);
    P.time = discrete ? hinf::TimeDomain::Discrete : hinf::TimeDomain::Continuous;
    P.sample_time = sample_time;
  }
  design.strictly_proper = c.boolean("strictly_proper", true);
  // 0 (the physical model's "off") or a positive radius
  if (c.has("pole_disk_radius") && (model ? c.nonnegative("pole_disk_radius") > 0 : true)) {
    design.pole_disk_radius = c.positive("pole_disk_radius");
    if (discrete && *design.pole_disk_radius > 1)
      c.fail("pole_disk_radius", "in discrete time the disk |z| < r must lie in the unit disk (r <= 1)");
  }
  return P;
}

}  // namespace

ControllerConfig parse_controller_config(const std::string& yaml_text, const std::string& source_name) {
  ControllerConfig config;
  config.path = source_name;
  config.sha256 = sha256_hex(yaml_text);
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(yaml_text, "empty config; expected a map with 'controller'");
  reader.check_map(root, "", {"controller", "solver"});
  try {
    config.plant = read_controller_section(reader, root["controller"], config.design);
    if (const YAML::Node solver = root["solver"]) {
      config.settings = read_solver_section(reader, solver);
      try {
        config.settings.validate();
      } catch (const Error& e) {
        const Error keyed = e.rekeyed("solver." + e.key());
        const YAML::Node at = solver[e.key()];
        throw Error(ErrorCode::InvalidInput, reader.location(at ? at : solver) + ": " + keyed.what(), keyed.key());
      }
    }
  } catch (const YAML::Exception& e) {
    throw Error(ErrorCode::InvalidInput, source_name + ": YAML error: " + e.what());
  }
  return config;
}

bool declares_controller(const std::string& yaml_text) {
  try {  // the same guards as every reader (one document, nesting depth)
    const YAML::Node root = YamlReader("config").load(yaml_text, "empty");
    return root.IsMap() && root["controller"];
  } catch (const Error&) {
    return false;  // parse_config will say why
  }
}

}  // namespace hinf::synth
