#include "hinf/common/yaml_reader.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>

#include "hinf/common/suggest.hpp"
#include "hinf/common/error.hpp"

namespace hinf {
namespace {

std::string node_kind(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null: return "an empty value";
    case YAML::NodeType::Scalar: return "the scalar '" + node.Scalar() + "'";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Undefined: return "nothing";
  }
  return "nothing";
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// YAML 1.2 core schema float: [-+]? ( \. [0-9]+ | [0-9]+ ( \. [0-9]* )? ) ( [eE] [-+]? [0-9]+ )?
bool is_core_float(const std::string& s) {
  size_t i = 0;
  const size_t n = s.size();
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  size_t int_digits = 0, frac_digits = 0;
  while (i < n && is_digit(s[i])) ++i, ++int_digits;
  if (i < n && s[i] == '.') {
    ++i;
    while (i < n && is_digit(s[i])) ++i, ++frac_digits;
  }
  if (int_digits == 0 && frac_digits == 0) return false;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    size_t exp_digits = 0;
    while (i < n && is_digit(s[i])) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  return i == n;
}

bool is_core_integer(const std::string& s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (!is_digit(s[i])) return false;
  return true;
}

}  // namespace

std::string child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string YamlReader::location(const YAML::Node& node) const {
  if (!node.IsDefined()) return source_;
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return source_;
  return source_ + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

void YamlReader::fail(const YAML::Node& at, const std::string& message) const {
  throw Error(ErrorCode::InvalidInput, location(at) + ": " + message);
}

void YamlReader::check_map(const YAML::Node& node, const std::string& path,
                           const std::vector<std::string>& allowed) const {
  const std::string name = path.empty() ? "the top level" : "'" + path + "'";
  if (!node.IsMap()) {
    if (node.IsNull())
      fail(node, name + " is empty; expected a map with keys from: " +
                     [&] {
                       std::string s;
                       for (const auto& a : allowed) s += (s.empty() ? "" : ", ") + a;
                       return s;
                     }());
    fail(node, name + " must be a map of keys, got " + node_kind(node));
  }
  if (node.size() == 0) fail(node, name + " is an empty map");
  std::set<std::string> seen;
  for (const auto& item : node) {
    const YAML::Node& key_node = item.first;
    if (!key_node.IsScalar())
      fail(key_node, "a key in " + name + " is " + node_kind(key_node) + "; keys must be names");
    const std::string key = key_node.Scalar();
    const std::string full = child_path(path, key);
    if (!seen.insert(key).second) fail(key_node, "duplicate key '" + full + "'");
    bool known = false;
    for (const auto& a : allowed) known = known || a == key;
    if (known) continue;
    std::string message = "unknown key '" + full + "'";
    if (const auto suggestion = closest_match(key, allowed)) {
      message += " (did you mean '" + *suggestion + "'?)";
    } else {
      message += " (allowed here: ";
      for (size_t i = 0; i < allowed.size(); ++i) message += (i ? ", " : "") + allowed[i];
      message += ")";
    }
    fail(key_node, message);
  }
}

std::string YamlReader::scalar_text(const YAML::Node& node, const std::string& path,
                                    const char* expected) const {
  if (!node.IsScalar())
    fail(node, path + ": expected " + expected + ", got " + node_kind(node));
  // yaml-cpp tags quoted scalars "!"; a quoted "1" is a string, not a number.
  if (node.Tag() == "!")
    fail(node, path + ": expected " + expected + ", got the quoted string \"" + node.Scalar() +
                   "\" (write numbers without quotes)");
  return node.Scalar();
}

double YamlReader::number(const YAML::Node& node, const std::string& path) const {
  const std::string s = scalar_text(node, path, "a number");
  if (s == ".inf" || s == ".Inf" || s == ".INF" || s == "+.inf" || s == "+.Inf" || s == "+.INF")
    return std::numeric_limits<double>::infinity();
  if (s == "-.inf" || s == "-.Inf" || s == "-.INF") return -std::numeric_limits<double>::infinity();
  if (s == ".nan" || s == ".NaN" || s == ".NAN") return std::numeric_limits<double>::quiet_NaN();
  if (!is_core_float(s)) fail(node, path + " = '" + s + "': not a number");
  errno = 0;
  const double v = std::strtod(s.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(v))
    fail(node, path + " = " + s + ": out of the range of a double");
  return v;  // underflow to a denormal or zero is accepted
}

int YamlReader::integer(const YAML::Node& node, const std::string& path) const {
  const std::string s = scalar_text(node, path, "an integer");
  if (!is_core_integer(s)) fail(node, path + " = '" + s + "': must be an integer");
  errno = 0;
  const long long v = std::strtoll(s.c_str(), nullptr, 10);
  if (errno == ERANGE || v < INT_MIN || v > INT_MAX)
    fail(node, path + " = " + s + ": out of the range of an int");
  return static_cast<int>(v);
}

unsigned YamlReader::unsigned_integer(const YAML::Node& node, const std::string& path) const {
  const std::string s = scalar_text(node, path, "a non-negative integer");
  if (!is_core_integer(s) || s[0] == '-')
    fail(node, path + " = '" + s + "': must be a non-negative integer");
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if (errno == ERANGE || v > UINT_MAX)
    fail(node, path + " = " + s + ": out of range (at most " + std::to_string(UINT_MAX) + ")");
  return static_cast<unsigned>(v);
}

bool YamlReader::boolean(const YAML::Node& node, const std::string& path) const {
  const std::string s = scalar_text(node, path, "true or false");
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  fail(node, path + " = '" + s + "': must be true or false");
}

std::string YamlReader::word(const YAML::Node& node, const std::string& path) const {
  if (!node.IsScalar()) fail(node, path + ": expected a word, got " + node_kind(node));
  return node.Scalar();
}

Eigen::MatrixXd YamlReader::matrix(const YAML::Node& node, const std::string& path) const {
  const auto entry_path = [&](size_t i, size_t j) {
    return path + " entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")";
  };
  const auto finite_entry = [&](const YAML::Node& e, const std::string& where) {
    const double v = number(e, where);
    if (!std::isfinite(v)) fail(e, where + " = " + e.Scalar() + ": not finite");
    return v;
  };

  if (node.IsMap()) {
    check_map(node, path, {"diag"});
    const YAML::Node diag = node["diag"];
    if (!diag) fail(node, path + ": missing key '" + child_path(path, "diag") + "'");
    const std::string dpath = child_path(path, "diag");
    if (!diag.IsSequence())
      fail(diag, dpath + ": expected a list of numbers, got " + node_kind(diag));
    if (diag.size() == 0) fail(diag, dpath + ": empty list (a matrix needs at least 1 entry)");
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(diag.size(), diag.size());
    for (size_t i = 0; i < diag.size(); ++i)
      M(i, i) = finite_entry(diag[i], dpath + " entry " + std::to_string(i + 1));
    return M;
  }
  if (!node.IsSequence())
    fail(node, path + ": expected a matrix (nested rows [[a, b], [c, d]] or {diag: [a, b]}), got " +
                   node_kind(node));
  if (node.size() == 0) fail(node, path + ": empty matrix ([]); it needs at least 1 row");
  const size_t rows = node.size();
  size_t cols = 0;
  for (size_t i = 0; i < rows; ++i) {
    const YAML::Node row = node[i];
    if (!row.IsSequence())
      fail(row, path + ": row " + std::to_string(i + 1) + " is " + node_kind(row) +
                    ", not a list (write a matrix as nested rows [[a, b], [c, d]]; "
                    "a column vector is [[a], [b]])");
    if (row.size() == 0) fail(row, path + ": row " + std::to_string(i + 1) + " is empty");
    if (i == 0) cols = row.size();
    if (row.size() != cols)
      fail(row, path + ": ragged rows: row " + std::to_string(i + 1) + " has " +
                    std::to_string(row.size()) + " entries, row 1 has " + std::to_string(cols));
  }
  Eigen::MatrixXd M(rows, cols);
  for (size_t i = 0; i < rows; ++i)
    for (size_t j = 0; j < cols; ++j) M(i, j) = finite_entry(node[i][j], entry_path(i, j));
  return M;
}

}  // namespace hinf
