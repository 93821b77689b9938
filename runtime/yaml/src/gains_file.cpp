// Reading a gains file (docs/file-formats.md, format hinf-gains/1) with yaml-cpp.
// Strict: unknown top-level keys, unknown keys in `filter` and `dimensions`,
// duplicate keys, non-numeric or non-finite entries and inconsistent shapes are
// errors whose message names the file, the position, the key path and the sizes.
#include "hinf/runtime_yaml/gains_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace hinf::runtime_yaml {
namespace {

constexpr const char* kFormat = "hinf-gains/1";

const std::vector<std::string>& allowed_top_level_keys() {
  static const std::vector<std::string> keys{"format",        "tool",   "config_sha256",
                                             "dimensions",    "gamma",  "gamma_squared",
                                             "filter",        "certificate", "solver",
                                             "timing"};
  return keys;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string did_you_mean(const std::string& key, const std::vector<std::string>& allowed) {
  std::string best;
  std::size_t best_d = 3;  // suggest only close matches (distance <= 2)
  for (const auto& candidate : allowed) {
    const std::size_t d = edit_distance(key, candidate);
    if (d < best_d) {
      best_d = d;
      best = candidate;
    }
  }
  return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& e : v) s += (s.empty() ? "" : ", ") + e;
  return s;
}

// Error reporting bound to one source (file name) so every message names it.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& key_path,
                         const std::string& what) const {
    std::ostringstream os;
    os << source_;
    const YAML::Mark mark = at.IsDefined() ? at.Mark() : YAML::Mark::null_mark();
    if (!mark.is_null()) os << ":" << mark.line + 1 << ":" << mark.column + 1;
    os << ": ";
    if (!key_path.empty()) os << key_path << ": ";
    os << what;
    throw GainsFileError(os.str());
  }

  // Checks `map` is a mapping whose keys are unique scalars drawn from `allowed`.
  void check_keys(const YAML::Node& map, const std::string& path,
                  const std::vector<std::string>& allowed) const {
    if (!map.IsMap()) fail(map, path, "expected a mapping");
    std::set<std::string> seen;
    for (const auto& kv : map) {
      if (!kv.first.IsScalar()) fail(kv.first, path, "keys must be plain names");
      const std::string key = kv.first.Scalar();
      const std::string full = path.empty() ? key : path + "." + key;
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
        fail(kv.first, full,
             "unknown key" + did_you_mean(key, allowed) + "; allowed: " + join(allowed));
      if (!seen.insert(key).second) fail(kv.first, full, "duplicate key");
    }
  }

  std::string scalar_string(const YAML::Node& node, const std::string& path) const {
    if (!node.IsScalar()) fail(node, path, "expected a string");
    return node.Scalar();
  }

  double finite_double(const YAML::Node& node, const std::string& path) const {
    if (!node.IsScalar()) fail(node, path, "expected a number");
    double v = 0.0;
    try {
      v = node.as<double>();
    } catch (const YAML::Exception&) {
      fail(node, path, "'" + node.Scalar() + "' is not a number");
    }
    if (!std::isfinite(v)) fail(node, path, "'" + node.Scalar() + "' is not finite");
    return v;
  }

  long positive_int(const YAML::Node& node, const std::string& path) const {
    if (!node.IsScalar()) fail(node, path, "expected a positive integer");
    long v = 0;
    try {
      v = node.as<long>();
    } catch (const YAML::Exception&) {
      fail(node, path, "'" + node.Scalar() + "' is not an integer");
    }
    if (v <= 0) fail(node, path, "must be positive, got " + std::to_string(v));
    return v;
  }

  // A nested row list [[a, b], [c, d]]: every row a sequence of the same length.
  Eigen::MatrixXd matrix(const YAML::Node& node, const std::string& path) const {
    if (!node.IsSequence())
      fail(node, path, "expected a matrix as a list of rows, e.g. [[1, 0], [0, 1]]");
    const std::size_t rows = node.size();
    if (rows == 0) fail(node, path, "matrix has no rows");
    const YAML::Node first = node[0];
    if (!first.IsSequence()) fail(first, path + "[0]", "expected a row (a list of numbers)");
    const std::size_t cols = first.size();
    if (cols == 0) fail(first, path + "[0]", "row is empty");
    Eigen::MatrixXd m(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    for (std::size_t i = 0; i < rows; ++i) {
      const YAML::Node row = node[i];
      const std::string row_path = path + "[" + std::to_string(i) + "]";
      if (!row.IsSequence()) fail(row, row_path, "expected a row (a list of numbers)");
      if (row.size() != cols)
        fail(row, row_path,
             "row has " + std::to_string(row.size()) + " entries, expected " +
                 std::to_string(cols) + " (the length of row 0)");
      for (std::size_t j = 0; j < cols; ++j)
        m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
            finite_double(row[j], row_path + "[" + std::to_string(j) + "]");
    }
    return m;
  }

 private:
  std::string source_;
};

std::string dims(Eigen::Index r, Eigen::Index c) {
  return std::to_string(r) + "x" + std::to_string(c);
}

}  // namespace

GainsFile parse_gains_yaml(const std::string& text, const std::string& source_name) {
  const Reader rd(source_name);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    std::ostringstream os;
    os << source_name;
    if (!e.mark.is_null()) os << ":" << e.mark.line + 1 << ":" << e.mark.column + 1;
    os << ": not valid YAML: " << e.msg;
    throw GainsFileError(os.str());
  }
  if (!root.IsDefined() || root.IsNull())
    throw GainsFileError(source_name + ": empty file; expected a gains file (format: " +
                         kFormat + ")");
  if (!root.IsMap()) rd.fail(root, "", "expected a mapping at the top level");
  rd.check_keys(root, "", allowed_top_level_keys());

  const YAML::Node format = root["format"];
  if (!format) rd.fail(root, "format", std::string("missing; expected 'format: ") + kFormat + "'");
  const std::string fmt = rd.scalar_string(format, "format");
  if (fmt != kFormat)
    rd.fail(format, "format", "unsupported format '" + fmt + "', expected '" + kFormat + "'");

  GainsFile g;
  if (const YAML::Node tool = root["tool"]) g.tool = rd.scalar_string(tool, "tool");
  if (const YAML::Node sha = root["config_sha256"]) {
    g.config_sha256 = rd.scalar_string(sha, "config_sha256");
    const bool hex64 = g.config_sha256.size() == 64 &&
                       std::all_of(g.config_sha256.begin(), g.config_sha256.end(), [](char c) {
                         return std::isxdigit(static_cast<unsigned char>(c)) != 0;
                       });
    if (!hex64)
      rd.fail(sha, "config_sha256",
              "expected 64 hexadecimal digits, got '" + g.config_sha256 + "'");
  }
  if (const YAML::Node gamma = root["gamma"]) {
    const double v = rd.finite_double(gamma, "gamma");
    if (v <= 0.0) rd.fail(gamma, "gamma", "must be positive");
    g.gamma = v;
  }
  if (const YAML::Node g2 = root["gamma_squared"]) {
    if (rd.finite_double(g2, "gamma_squared") <= 0.0)
      rd.fail(g2, "gamma_squared", "must be positive");
  }

  const YAML::Node filter = root["filter"];
  if (!filter) rd.fail(root, "filter", "missing; expected 'filter: {A_F: ..., B_F: ..., C_F: ...}'");
  rd.check_keys(filter, "filter", {"A_F", "B_F", "C_F"});
  for (const char* key : {"A_F", "B_F", "C_F"})
    if (!filter[key]) rd.fail(filter, std::string("filter.") + key, "missing");
  g.A_F = rd.matrix(filter["A_F"], "filter.A_F");
  g.B_F = rd.matrix(filter["B_F"], "filter.B_F");
  g.C_F = rd.matrix(filter["C_F"], "filter.C_F");

  const Eigen::Index n = g.A_F.rows();
  if (g.A_F.cols() != n)
    rd.fail(filter["A_F"], "filter.A_F",
            "must be square (n x n), got " + dims(g.A_F.rows(), g.A_F.cols()));
  if (g.B_F.rows() != n)
    rd.fail(filter["B_F"], "filter.B_F",
            "expected " + std::to_string(n) + " rows (n x m, n = " + std::to_string(n) +
                " from filter.A_F), got " + dims(g.B_F.rows(), g.B_F.cols()));
  if (g.C_F.cols() != n)
    rd.fail(filter["C_F"], "filter.C_F",
            "expected " + std::to_string(n) + " columns (l x n, n = " + std::to_string(n) +
                " from filter.A_F), got " + dims(g.C_F.rows(), g.C_F.cols()));

  if (const YAML::Node d = root["dimensions"]) {
    rd.check_keys(d, "dimensions", {"n", "m", "l"});
    const struct {
      const char* key;
      Eigen::Index actual;
      const char* from;
    } checks[] = {{"n", n, "rows of filter.A_F"},
                  {"m", g.B_F.cols(), "columns of filter.B_F"},
                  {"l", g.C_F.rows(), "rows of filter.C_F"}};
    for (const auto& c : checks) {
      const YAML::Node v = d[c.key];
      if (!v) continue;
      const long declared = rd.positive_int(v, std::string("dimensions.") + c.key);
      if (declared != c.actual)
        rd.fail(v, std::string("dimensions.") + c.key,
                "declares " + std::to_string(declared) + " but the filter has " +
                    std::to_string(c.actual) + " (" + c.from + "; filter.A_F " +
                    dims(g.A_F.rows(), g.A_F.cols()) + ", filter.B_F " +
                    dims(g.B_F.rows(), g.B_F.cols()) + ", filter.C_F " +
                    dims(g.C_F.rows(), g.C_F.cols()) + ")");
    }
  }
  return g;
}

GainsFile load_gains_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
    throw GainsFileError(path + ": cannot read gains file: no such file");
  if (std::filesystem::is_directory(status))
    throw GainsFileError(path + ": cannot read gains file: is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw GainsFileError(path + ": cannot read gains file: cannot open (permissions?)");
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) throw GainsFileError(path + ": cannot read gains file: read error");
  return parse_gains_yaml(buf.str(), path);
}

}  // namespace hinf::runtime_yaml
