// Reading a gains file (docs/file-formats.md, format hinf-gains/1) with the project's one
// strict YAML reader (hinf::YamlReader, common/): unknown top-level keys, unknown keys in
// `filter` and `dimensions`, duplicate keys, quoted, non-numeric or non-finite entries and
// inconsistent shapes are Error(InvalidInput) whose message names the file, the position,
// the key path and the sizes.
#include "hinf/runtime_yaml/gains_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "hinf/common/error.hpp"
#include "hinf/common/input_file.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "file_header.hpp"

namespace hinf::runtime_yaml {
namespace {

constexpr const char* kFormat = "hinf-gains/1";

const std::vector<std::string>& allowed_top_level_keys() {
  static const std::vector<std::string> keys{"format",        "tool",   "config_sha256",
                                             "dimensions",    "gamma",  "gamma_squared",
                                             "filter",        "certificate", "solver",
                                             "timing",        "bound",
                                             "sample_time"};
  return keys;
}

std::string dims(const Eigen::MatrixXd& m) {
  return std::to_string(m.rows()) + "x" + std::to_string(m.cols());
}

// format (required and exactly kFormat), tool, config_sha256, gamma, gamma_squared.
void read_header(const YamlMap& top, GainsFile& g) {
  top.required("format", std::string("expected 'format: ") + kFormat + "'");
  const std::string format = top.word("format");
  if (format != kFormat)
    top.fail("format", "unsupported format '" + format + "', expected '" + kFormat + "'");
  g.tool = top.word("tool", "");
  g.config_sha256 = read_config_sha256(top);
  if (top.has("gamma")) g.gamma = top.positive("gamma");
  if (top.has("sample_time")) g.sample_time = top.positive("sample_time");
  if (top.has("gamma_squared")) top.positive("gamma_squared");
}

// An observer-form filter's gains: K (n×m, required), and for the filtered estimate
// (docs/maths.md §18.6) M (n×m) and the feedthrough D_F (l×m), both required.
void read_observer_gains(const YamlMap& filter, GainsFile& g) {
  filter.required("K", "an observer-form filter carries its gain K (A_F = A - K C, B_F = K)");
  g.K = filter.matrix("K", MatrixForms::RowsOnly);
  if (g.K.rows() != g.B_F.rows() || g.K.cols() != g.B_F.cols())
    filter.fail("K", "expected " + dims(g.B_F) + " (the shape of filter.B_F), got " + dims(g.K));
  if (!g.filtered) return;
  filter.required("M", "a filtered estimate carries its gain M (x_hat(k|k) = x_hat + M (y - C x_hat))");
  filter.required("D_F", "a filtered estimate carries its feedthrough D_F (z_F = C_F x_F + D_F y)");
  g.M = filter.matrix("M", MatrixForms::RowsOnly);
  g.D_F = filter.matrix("D_F", MatrixForms::RowsOnly);
  if (g.M.rows() != g.B_F.rows() || g.M.cols() != g.B_F.cols())
    filter.fail("M", "expected " + dims(g.B_F) + " (the shape of filter.B_F), got " + dims(g.M));
  if (g.D_F.rows() != g.C_F.rows() || g.D_F.cols() != g.B_F.cols())
    filter.fail("D_F", "expected " + std::to_string(g.C_F.rows()) + "x" + std::to_string(g.B_F.cols()) +
                           " (l x m: rows of filter.C_F, columns of filter.B_F), got " + dims(g.D_F));
}

// filter: {form, estimate, A_F: n×n, B_F: n×m, C_F: l×n, D_F: l×m, K: n×m, M: n×m, G_F: n×r}
// (docs/maths.md (5)-(6), (121), (140)), nested rows only; K only (and then required) in
// observer form, M and D_F only (and then required) for its filtered estimate.
void read_filter(const YamlMap& top, GainsFile& g) {
  top.required("filter", "expected 'filter: {A_F: ..., B_F: ..., C_F: ...}'");
  const YamlMap filter = top.map("filter", {"form", "estimate", "A_F", "B_F", "C_F", "D_F", "K", "M", "G_F"});
  g.observer_form = filter.choice("form", {"augmented", "observer"}, "augmented") == "observer";
  g.filtered = filter.choice("estimate", {"predicted", "filtered"}, "predicted") == "filtered";
  if (g.filtered && !g.observer_form)
    filter.fail("estimate", "only an observer-form filter (filter.form: observer) has a filtered estimate");
  for (const char* key : {"M", "D_F"})
    if (!g.filtered && filter.has(key))
      filter.fail(key, "only a filtered estimate (filter.estimate: filtered) has " + std::string(key));
  g.A_F = filter.matrix("A_F", MatrixForms::RowsOnly);
  g.B_F = filter.matrix("B_F", MatrixForms::RowsOnly);
  g.C_F = filter.matrix("C_F", MatrixForms::RowsOnly);
  if (!g.observer_form && filter.has("K"))
    filter.fail("K", "only an observer-form filter (filter.form: observer) has a gain K");
  g.G_F = filter.has("G_F") ? filter.matrix("G_F", MatrixForms::RowsOnly) : Eigen::MatrixXd::Zero(g.A_F.rows(), 0);
  const std::string n = std::to_string(g.A_F.rows());
  if (g.A_F.cols() != g.A_F.rows())
    filter.fail("A_F", "must be square (n x n), got " + dims(g.A_F));
  if (g.B_F.rows() != g.A_F.rows())
    filter.fail("B_F", "expected " + n + " rows (n x m, n = " + n + " from filter.A_F), got " +
                           dims(g.B_F));
  if (g.C_F.cols() != g.A_F.rows())
    filter.fail("C_F", "expected " + n + " columns (l x n, n = " + n +
                           " from filter.A_F), got " + dims(g.C_F));
  if (g.observer_form) read_observer_gains(filter, g);
  if (filter.has("G_F") && g.G_F.rows() != g.A_F.rows())
    filter.fail("G_F", "expected " + n + " rows (n x r, n = " + n + " from filter.A_F), got " + dims(g.G_F));
}

// dimensions: {n, m, l} (optional, each optional): positive and as the matrices say.
void check_dimensions(const YamlMap& top, const GainsFile& g) {
  if (!top.has("dimensions")) return;
  const YamlMap d = top.map("dimensions", {"n", "m", "l", "r"});
  const struct {
    const char* key;
    Eigen::Index actual;
    const char* from;
  } checks[] = {{"n", g.A_F.rows(), "rows of filter.A_F"},
                {"m", g.B_F.cols(), "columns of filter.B_F"},
                {"l", g.C_F.rows(), "rows of filter.C_F"},
                {"r", g.G_F.cols(), "columns of filter.G_F"}};
  for (const auto& c : checks) {
    if (!d.has(c.key)) continue;
    const int declared = d.integer(c.key);
    if (declared <= 0) d.fail_value(c.key, declared, "must be > 0");
    if (declared != c.actual)
      d.fail(c.key, "declares " + std::to_string(declared) + " but the filter has " +
                        std::to_string(c.actual) + " (" + c.from + "; filter.A_F " + dims(g.A_F) +
                        ", filter.B_F " + dims(g.B_F) + ", filter.C_F " + dims(g.C_F) + ")");
  }
}


}  // namespace

GainsFile parse_gains_yaml(const std::string& text, const std::string& source_name) {
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(
      text, std::string("empty file; expected a gains file (format: ") + kFormat + ")");
  const YamlMap top = reader.map(root, "", allowed_top_level_keys());
  GainsFile g;
  read_header(top, g);
  read_filter(top, g);
  check_dimensions(top, g);
  return g;
}

GainsFile load_gains_file(const std::string& path) {
  return parse_gains_yaml(read_input_file(path, "gains file", kMaxGainsBytes), path);
}

}  // namespace hinf::runtime_yaml
