#include "hinf/common/yaml_reader.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/suggest.hpp"

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

bool is_core_integer(const std::string& s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (!is_digit(s[i])) return false;
  return true;
}

std::string dims(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + "x" + std::to_string(cols);
}

// "'a'", "'a' or 'b'", "one of 'a', 'b', 'c'".
std::string alternatives(const std::vector<std::string>& options) {
  if (options.size() == 1) return "'" + options[0] + "'";
  if (options.size() == 2) return "'" + options[0] + "' or '" + options[1] + "'";
  std::string s = "one of ";
  for (size_t i = 0; i < options.size(); ++i) s += (i ? ", '" : "'") + options[i] + "'";
  return s;
}

std::string key_list(const std::vector<std::string>& keys) {
  std::string s;
  for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

}  // namespace

std::string child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string YamlReader::location(const YAML::Node& node) const {
  return node.IsDefined() ? location_of(node.Mark()) : source_;
}

void YamlReader::fail(const YAML::Node& at, const std::string& message) const {
  throw Error(ErrorCode::InvalidInput, location(at) + ": " + message);
}

std::string YamlReader::location_of(const YAML::Mark& mark) const {
  if (mark.is_null()) return source_;
  return source_ + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

namespace {

// Counts the documents of a YAML stream, with the mark of each one's first node, without
// building them. yaml-cpp 0.7's LoadAll loops for ever on a stray ',' outside [ ] or { }
// (each pass yields an empty document and consumes nothing, allocating until memory runs
// out: found by fuzz/fuzz_gains, 444 bytes reached 21 GB); a document that starts where
// the previous one did is that stall, and ends the count.
class DocumentCounter final : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override { starts.push_back(mark); first_node.emplace_back(); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override { node(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnMapEnd() override {}
  bool stalled() const {
    const std::size_t n = starts.size();
    return n >= 2 && starts[n - 1].pos == starts[n - 2].pos;
  }

  std::vector<YAML::Mark> starts;
  std::vector<std::optional<YAML::Mark>> first_node;

 private:
  void node(const YAML::Mark& mark) {
    if (!first_node.empty() && !first_node.back()) first_node.back() = mark;
  }
};

// Documents counted before giving up: more than one is refused anyway.
constexpr std::size_t kMaxDocumentsCounted = 100;

}  // namespace

YAML::Node YamlReader::load(const std::string& text, const std::string& empty_message) const {
  YAML::Node document;
  try {
    std::istringstream stream(text);
    YAML::Parser parser(stream);
    DocumentCounter counter;
    while (counter.starts.size() < kMaxDocumentsCounted && !counter.stalled() && parser.HandleNextDocument(counter)) {
    }
    if (counter.stalled())
      throw Error(ErrorCode::InvalidInput,
                  location_of(counter.starts.back()) + ": YAML syntax error: the parser cannot read past this "
                                                       "point (a ',', ']' or '}' outside [ ] or { }?)");
    const std::size_t documents = counter.starts.size();
    if (documents > 1) {
      const YAML::Mark at = counter.first_node[1] ? *counter.first_node[1] : counter.starts[1];
      throw Error(ErrorCode::InvalidInput,
                  location_of(at) + ": the file holds " + (documents < kMaxDocumentsCounted ? "" : "at least ") +
                      std::to_string(documents) + " YAML documents; it must be exactly one");
    }
    document = YAML::Load(text);  // the one document (a stream without any gives Null)
  } catch (const YAML::DeepRecursion& e) {  // yaml-cpp's own guard of its recursive parser
    throw Error(ErrorCode::InvalidInput,
                location_of(e.mark) + ": lists or maps nested " + std::to_string(e.depth()) +
                    " levels deep; no format of this project nests more than 4 (a config's hill.B.diag)");
  } catch (const YAML::ParserException& e) {
    throw Error(ErrorCode::InvalidInput, location_of(e.mark) + ": YAML syntax error: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw Error(ErrorCode::InvalidInput, source_ + ": YAML error: " + e.what());
  }
  if (!document || document.IsNull()) throw Error(ErrorCode::InvalidInput, source_ + ": " + empty_message);
  return document;
}

void YamlReader::check_map(const YAML::Node& node, const std::string& path,
                           const std::vector<std::string>& allowed, EmptyMap empty) const {
  const std::string name = path.empty() ? "the top level" : "'" + path + "'";
  if (empty == EmptyMap::Allowed && (node.IsNull() || (node.IsMap() && node.size() == 0))) return;
  if (!node.IsMap()) {
    if (node.IsNull())
      fail(node, name + " is empty; expected a map with keys from: " + key_list(allowed));
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
    } else if (allowed.empty()) {
      message += " (no keys are allowed here)";
    } else {
      message += " (allowed here: " + key_list(allowed) + ")";
    }
    fail(key_node, message);
  }
}

YamlMap YamlReader::map(const YAML::Node& node, const std::string& path,
                        const std::vector<std::string>& allowed, EmptyMap empty) const {
  check_map(node, path, allowed, empty);
  return YamlMap(*this, node, path);
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
  if (!is_decimal_number(s)) fail(node, path + " = '" + s + "': not a number");
  errno = 0;
  const double v = std::strtod(s.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(v))
    fail(node, path + " = " + s + ": out of the range of a double");
  return v;  // underflow to a denormal or zero is accepted
}

double YamlReader::finite_number(const YAML::Node& node, const std::string& path) const {
  const double v = number(node, path);
  if (!std::isfinite(v)) fail(node, path + " = " + node.Scalar() + ": not finite");
  return v;
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

std::string YamlReader::choice(const YAML::Node& node, const std::string& path,
                              const std::vector<std::string>& options) const {
  const std::string s = word(node, path);
  for (const auto& o : options)
    if (s == o) return s;
  std::string message = path + " = '" + s + "': must be " + alternatives(options);
  if (const auto guess = closest_match(s, options)) message += " (did you mean '" + *guess + "'?)";
  fail(node, message);
}

void YamlReader::require_dimension(const YAML::Node& node, const std::string& path, const char* what,
                                   size_t count) const {
  if (count > kMaxMatrixDimension)
    fail(node, path + ": " + std::to_string(count) + " " + what + "; a vector or matrix read from a file has at most " +
                   std::to_string(kMaxMatrixDimension) + " (checked before any memory is allocated)");
}

Eigen::VectorXd YamlReader::vector(const YAML::Node& node, const std::string& path,
                                   Eigen::Index size) const {
  const std::string expected =
      size >= 0 ? "a list of " + std::to_string(size) + " numbers" : "a list of numbers";
  if (!node.IsSequence()) fail(node, path + ": expected " + expected + ", got " + node_kind(node));
  if (node.size() == 0) fail(node, path + ": empty list; expected " + expected);
  const auto n = static_cast<Eigen::Index>(node.size());
  if (size >= 0 && n != size)
    fail(node, path + ": expected " + expected + ", got " + std::to_string(n));
  require_dimension(node, path, "entries", node.size());
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i)
    v(i) = finite_number(node[static_cast<size_t>(i)], path + " entry " + std::to_string(i + 1));
  return v;
}

Eigen::MatrixXd YamlReader::matrix(const YAML::Node& node, const std::string& path,
                                   MatrixForms forms) const {
  return matrix(
      node, path,
      [this](const YAML::Node& entry, const std::string& entry_path, Eigen::Index, Eigen::Index) {
        return finite_number(entry, entry_path);
      },
      forms);
}

Eigen::MatrixXd YamlReader::matrix(const YAML::Node& node, const std::string& path, const EntryReader& entry,
                                   MatrixForms forms) const {
  if (node.IsMap() && forms == MatrixForms::RowsOrDiag) {
    check_map(node, path, {"diag"});
    const YAML::Node diag = node["diag"];
    const std::string diag_path = child_path(path, "diag");
    if (!diag) fail(node, path + ": missing key '" + diag_path + "'");
    if (!diag.IsSequence()) fail(diag, diag_path + ": expected a list of numbers, got " + node_kind(diag));
    if (diag.size() == 0) fail(diag, diag_path + ": empty list; expected a list of numbers");
    require_dimension(diag, diag_path, "entries", diag.size());
    const auto n = static_cast<Eigen::Index>(diag.size());
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      M(i, i) = entry(diag[static_cast<size_t>(i)], diag_path + " entry " + std::to_string(i + 1), i, i);
    return M;
  }
  if (!node.IsSequence())
    fail(node, path + (forms == MatrixForms::RowsOrDiag
                           ? ": expected a matrix (nested rows [[a, b], [c, d]] or {diag: [a, b]}), got "
                           : ": expected a matrix as nested rows [[a, b], [c, d]], got ") +
                   node_kind(node));
  if (node.size() == 0) fail(node, path + ": empty matrix ([]); it needs at least 1 row");
  require_dimension(node, path, "rows", node.size());
  const size_t rows = node.size();
  size_t cols = 0;
  for (size_t i = 0; i < rows; ++i) {
    const YAML::Node row = node[i];
    if (!row.IsSequence())
      fail(row, path + ": row " + std::to_string(i + 1) + " is " + node_kind(row) +
                    ", not a list (write a matrix as nested rows [[a, b], [c, d]]; "
                    "a column vector is [[a], [b]])");
    if (row.size() == 0) fail(row, path + ": row " + std::to_string(i + 1) + " is empty");
    require_dimension(row, path + " row " + std::to_string(i + 1), "entries", row.size());
    if (i == 0) cols = row.size();
    if (row.size() != cols)
      fail(row, path + ": ragged rows: row " + std::to_string(i + 1) + " has " +
                    std::to_string(row.size()) + " entries, row 1 has " + std::to_string(cols));
  }
  Eigen::MatrixXd M(rows, cols);
  for (size_t i = 0; i < rows; ++i)
    for (size_t j = 0; j < cols; ++j)
      M(i, j) = entry(node[i][j], path + " entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")",
                      static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  return M;
}

Eigen::MatrixXd YamlReader::matrix(const YAML::Node& node, const std::string& path,
                                   Eigen::Index rows, Eigen::Index cols, MatrixForms forms) const {
  Eigen::MatrixXd M = matrix(node, path, forms);
  if (M.rows() != rows || M.cols() != cols)
    fail(node, path + ": expected a " + dims(rows, cols) + " matrix, got " + dims(M.rows(), M.cols()));
  return M;
}

std::vector<std::pair<YAML::Node, std::string>> YamlReader::one_or_list(
    const YAML::Node& node, const std::string& path) const {
  if (node.IsMap()) return {{node, path}};
  if (!node.IsSequence())
    fail(node, path + ": expected a map or a list of maps, got " + node_kind(node));
  std::vector<std::pair<YAML::Node, std::string>> items;
  for (size_t i = 0; i < node.size(); ++i)
    items.emplace_back(node[i], path + "[" + std::to_string(i) + "]");
  return items;
}

// ---- YamlMap ------------------------------------------------------------------------

bool YamlMap::has(const std::string& key) const { return static_cast<bool>(get(key)); }

YAML::Node YamlMap::get(const std::string& key) const {
  if (!node_.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  const YAML::Node& map = node_;  // const lookup: never inserts into the tree
  return map[key];
}

YAML::Node YamlMap::required(const std::string& key, const std::string& what) const {
  const YAML::Node value = get(key);
  if (!value)
    reader_->fail(node_, "missing key '" + path_of(key) + "'" + (what.empty() ? "" : " (" + what + ")"));
  return value;
}

void YamlMap::fail(const std::string& key, const std::string& what) const {
  const YAML::Node value = get(key);
  reader_->fail(value ? value : node_, path_of(key) + ": " + what);
}

void YamlMap::fail_value(const std::string& key, double value, const std::string& rule) const {
  const YAML::Node at = get(key);
  reader_->fail(at ? at : node_, path_of(key) + " = " + number_text(value) + ": " + rule);
}

YamlMap YamlMap::map(const std::string& key, const std::vector<std::string>& allowed,
                     EmptyMap empty) const {
  return reader_->map(required(key), path_of(key), allowed, empty);
}

double YamlMap::number(const std::string& key) const {
  return reader_->number(required(key), path_of(key));
}
double YamlMap::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}
double YamlMap::finite(const std::string& key) const {
  return reader_->finite_number(required(key), path_of(key));
}
double YamlMap::finite(const std::string& key, double fallback) const {
  return has(key) ? finite(key) : fallback;
}
double YamlMap::positive(const std::string& key) const {
  const double v = finite(key);
  if (!(v > 0)) fail_value(key, v, "must be > 0");
  return v;
}
double YamlMap::positive(const std::string& key, double fallback) const {
  return has(key) ? positive(key) : fallback;
}
double YamlMap::nonnegative(const std::string& key) const {
  const double v = finite(key);
  if (v < 0) fail_value(key, v, "must be >= 0");
  return v;
}
double YamlMap::nonnegative(const std::string& key, double fallback) const {
  return has(key) ? nonnegative(key) : fallback;
}
int YamlMap::integer(const std::string& key) const {
  return reader_->integer(required(key), path_of(key));
}
int YamlMap::integer(const std::string& key, int fallback) const {
  return has(key) ? integer(key) : fallback;
}
bool YamlMap::boolean(const std::string& key, bool fallback) const {
  return has(key) ? reader_->boolean(get(key), path_of(key)) : fallback;
}
std::string YamlMap::word(const std::string& key) const {
  return reader_->word(required(key), path_of(key));
}
std::string YamlMap::word(const std::string& key, const std::string& fallback) const {
  return has(key) ? word(key) : fallback;
}
std::string YamlMap::choice(const std::string& key, const std::vector<std::string>& options) const {
  return reader_->choice(required(key), path_of(key), options);
}
std::string YamlMap::choice(const std::string& key, const std::vector<std::string>& options,
                            const std::string& fallback) const {
  return has(key) ? choice(key, options) : fallback;
}
Eigen::VectorXd YamlMap::vector(const std::string& key, Eigen::Index size) const {
  return reader_->vector(required(key), path_of(key), size);
}
Eigen::MatrixXd YamlMap::matrix(const std::string& key, MatrixForms forms) const {
  return reader_->matrix(required(key), path_of(key), forms);
}
Eigen::MatrixXd YamlMap::matrix(const std::string& key, Eigen::Index rows, Eigen::Index cols,
                                MatrixForms forms) const {
  return reader_->matrix(required(key), path_of(key), rows, cols, forms);
}

}  // namespace hinf
