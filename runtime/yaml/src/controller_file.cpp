// parse_controller_yaml, load_controller_file (controller_file.hpp).
#include "hinf/runtime_yaml/controller_file.hpp"

#include <vector>

#include "hinf/common/error.hpp"
#include "hinf/common/input_file.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "file_header.hpp"

namespace hinf::runtime_yaml {
namespace {

constexpr const char* kFormat = "hinf-controller/1";

std::string dims(const Eigen::MatrixXd& m) { return std::to_string(m.rows()) + "x" + std::to_string(m.cols()); }

// controller: {A_K, B_K, C_K, D_K, strictly_proper, pole_disk_radius}, shapes consistent.
void read_matrices(const YamlMap& top, ControllerFile& k) {
  top.required("controller", "expected 'controller: {A_K: ..., B_K: ..., C_K: ..., D_K: ...}'");
  const YamlMap c = top.map("controller", {"strictly_proper", "pole_disk_radius", "A_K", "B_K", "C_K", "D_K"});
  c.boolean("strictly_proper", true);
  if (c.has("pole_disk_radius")) c.positive("pole_disk_radius");
  for (const char* key : {"A_K", "B_K", "C_K", "D_K"}) c.required(key, "a matrix of the controller, docs/maths.md (146)");
  k.A_K = c.matrix("A_K", MatrixForms::RowsOnly);
  k.B_K = c.matrix("B_K", MatrixForms::RowsOnly);
  k.C_K = c.matrix("C_K", MatrixForms::RowsOnly);
  k.D_K = c.matrix("D_K", MatrixForms::RowsOnly);
  const std::string n = std::to_string(k.A_K.rows());
  if (k.A_K.cols() != k.A_K.rows()) c.fail("A_K", "must be square, got " + dims(k.A_K));
  if (k.B_K.rows() != k.A_K.rows()) c.fail("B_K", "expected " + n + " rows (n_K from A_K), got " + dims(k.B_K));
  if (k.C_K.cols() != k.A_K.rows()) c.fail("C_K", "expected " + n + " columns (n_K from A_K), got " + dims(k.C_K));
  if (k.D_K.rows() != k.C_K.rows() || k.D_K.cols() != k.B_K.cols())
    c.fail("D_K", "expected " + std::to_string(k.C_K.rows()) + "x" + std::to_string(k.B_K.cols()) +
                      " (rows of C_K x columns of B_K), got " + dims(k.D_K));
}

}  // namespace

ControllerFile parse_controller_yaml(const std::string& text, const std::string& source_name) {
  const YamlReader reader(source_name);
  const YAML::Node root =
      reader.load(text, std::string("empty file; expected a controller file (format: ") + kFormat + ")");
  // the format first: a gains file given for a controller file is named as such
  if (root.IsMap() && root["format"] && reader.word(root["format"], "format") != kFormat)
    reader.fail(root["format"], "format: unsupported format '" + reader.word(root["format"], "format") +
                                    "', expected '" + kFormat + "'");
  const YamlMap top = reader.map(root, "", {"format", "tool", "config_sha256", "time", "sample_time", "dimensions",
                                            "gamma", "gamma_optimal", "gamma_backoff", "gamma_without_disk", "robust_synthesis", "bound", "discretised", "controller", "closed_loop_poles",
                                            "certificate", "solver", "timing"});
  top.required("format", std::string("expected 'format: ") + kFormat + "'");
  if (top.word("format") != kFormat)
    top.fail("format", "unsupported format '" + top.word("format") + "', expected '" + kFormat + "'");
  ControllerFile k;
  k.tool = top.word("tool", "");
  k.config_sha256 = read_config_sha256(top);
  top.required("time", "continuous or discrete");
  k.discrete = top.choice("time", {"continuous", "discrete"}) == "discrete";
  if (k.discrete) {
    top.required("sample_time", "a discrete-time controller's period, s");
    k.sample_time = top.positive("sample_time");
  } else if (top.has("sample_time")) {
    top.fail("sample_time", "only with time: discrete");
  }
  if (top.has("gamma")) k.gamma = top.nonnegative("gamma");  // 0: T_zw ≡ 0 (γ* = 0 exactly)
  if (top.has("discretised")) {
    if (!k.discrete) top.fail("discretised", "only with time: discrete");
    const YamlMap d = top.map("discretised", {"method", "continuous_gamma", "plant_sampling"});
    d.required("method", "tustin or zoh");
    k.discretised = Discretised{d.choice("method", {"tustin", "zoh"}), std::nullopt};
    if (d.has("continuous_gamma")) k.discretised->continuous_gamma = d.nonnegative("continuous_gamma");
    if (d.has("plant_sampling")) d.choice("plant_sampling", {"zoh"});
  }
  read_matrices(top, k);
  if (top.has("dimensions")) {
    const YamlMap d = top.map("dimensions", {"n_K", "ny", "nu"});
    const struct {
      const char* key;
      Eigen::Index actual;
    } checks[] = {{"n_K", k.A_K.rows()}, {"ny", k.B_K.cols()}, {"nu", k.C_K.rows()}};
    for (const auto& c : checks)
      if (d.has(c.key) && d.integer(c.key) != c.actual)
        d.fail(c.key, "declares " + std::to_string(d.integer(c.key)) + " but the controller has " +
                          std::to_string(c.actual));
  }
  return k;
}

ControllerFile load_controller_file(const std::string& path) {
  return parse_controller_yaml(read_input_file(path, "controller file", kMaxGainsBytes), path);
}

}  // namespace hinf::runtime_yaml
