// parse_controller_config: `controller:` and `solver:` (controller_config.hpp).
#include "config/sections.hpp"
#include "config/sha256.hpp"
#include "hinf/common/error.hpp"
#include "hinf/synth/controller_config.hpp"

namespace hinf::synth {

namespace {

// A matrix of `controller:` with the shape the others fix (rows, cols; −1: free).
Eigen::MatrixXd plant_matrix(const YamlMap& c, const char* key, Eigen::Index rows, Eigen::Index cols) {
  c.required(key, "a matrix of the generalised plant, docs/maths.md (145)");
  if (rows < 0 || cols < 0) return c.matrix(key);
  return c.matrix(key, rows, cols);
}

hinf::GeneralisedPlant read_controller_section(const YamlReader& reader, const YAML::Node& node, ControllerDesign& design) {
  const YamlMap c = reader.map(node, "controller",
                               {"time", "sample_time", "A", "B1", "B2", "C1", "C2", "D11", "D12", "D21",
                                "strictly_proper", "pole_disk_radius"});
  hinf::GeneralisedPlant P;
  c.required("time", "continuous or discrete");
  P.time = c.choice("time", {"continuous", "discrete"}) == "discrete" ? hinf::TimeDomain::Discrete
                                                                       : hinf::TimeDomain::Continuous;
  if (P.time == hinf::TimeDomain::Discrete) {
    c.required("sample_time", "the controller's period in discrete time, s");
    P.sample_time = c.positive("sample_time");
  } else if (c.has("sample_time")) {
    c.fail("sample_time", "only with controller.time: discrete (a continuous-time controller has no period)");
  }
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
  design.strictly_proper = c.boolean("strictly_proper", true);
  if (c.has("pole_disk_radius")) {
    design.pole_disk_radius = c.positive("pole_disk_radius");
    if (P.time == hinf::TimeDomain::Discrete && *design.pole_disk_radius > 1)
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
