// Strict, typed reading of yaml-cpp nodes: the one reader of every YAML input of the
// project — configs (synth/src/config), gains files (runtime/yaml) and scenario files
// (sim/src/scenario_yaml.cpp); docs/file-formats.md.
// Every failure throws Error(InvalidInput) "<source>:<line>:<col>: <key path>...: <what>":
// unknown keys (with a did-you-mean from hinf::closest_match), duplicate keys, quoted
// numbers, non-finite or non-numeric entries and ill-formed matrices are refused the same
// way in every format.
#pragma once
#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace hinf {

// "a.b" from ("a", "b"); "b" from ("", "b").
std::string child_path(const std::string& parent, const std::string& key);

// Whether a map may be empty (`ekf: {}`, or no value at all) or must hold a key.
enum class EmptyMap { Refused, Allowed };
// Whether a matrix may also be written {diag: [a, b]} or only as nested rows.
enum class MatrixForms { RowsOrDiag, RowsOnly };

class YamlMap;

// The largest vector length and matrix row or column count any format reads: checked
// before allocating, so that a small file ({diag: [30000 numbers]}, or rows repeated by
// YAML aliases) cannot ask for gigabytes (a 1000×1000 matrix is 8 MB). Far above what
// the solver takes (docs/benchmarks.md).
constexpr std::size_t kMaxMatrixDimension = 1000;

class YamlReader {
 public:
  explicit YamlReader(std::string source) : source_(std::move(source)) {}

  const std::string& source() const { return source_; }

  // "<source>:<line>:<col>" of a node (1-based), or "<source>" if it has no mark.
  std::string location(const YAML::Node& node) const;

  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const;

  // The one YAML document of `text`: a syntax error gives its file:line:col, more than
  // one document is refused, and no document at all (empty, comments only) fails with
  // "<source>: <empty_message>".
  YAML::Node load(const std::string& text, const std::string& empty_message) const;

  // `node` must be a map (non-empty unless `empty` allows it; with Allowed, no value at
  // all counts as an empty map) whose keys are distinct plain scalars from `allowed`;
  // an unknown key is reported with its full path and the closest allowed key.
  void check_map(const YAML::Node& node, const std::string& path,
                 const std::vector<std::string>& allowed,
                 EmptyMap empty = EmptyMap::Refused) const;
  // check_map, then a view that reads the map's values by key.
  YamlMap map(const YAML::Node& node, const std::string& path,
              const std::vector<std::string>& allowed, EmptyMap empty = EmptyMap::Refused) const;

  // A plain scalar read as a YAML 1.2 core-schema float (also .inf, .nan); may be
  // non-finite, the caller's range check says why that is wrong.
  double number(const YAML::Node& node, const std::string& path) const;
  // number(), refusing .inf and .nan: "<path> = .nan: not finite".
  double finite_number(const YAML::Node& node, const std::string& path) const;
  // A decimal integer in the range of int / unsigned.
  int integer(const YAML::Node& node, const std::string& path) const;
  unsigned unsigned_integer(const YAML::Node& node, const std::string& path) const;
  // true / false (YAML 1.2 core: also True, TRUE, False, FALSE).
  bool boolean(const YAML::Node& node, const std::string& path) const;
  // A plain or quoted scalar string.
  std::string word(const YAML::Node& node, const std::string& path) const;
  // A word from `options` (a string enum): "<path> = 'eular': must be 'euler' or 'zoh'
  // (did you mean 'euler'?)".
  std::string choice(const YAML::Node& node, const std::string& path,
                     const std::vector<std::string>& options) const;

  // A non-empty list of finite numbers [a, b, c]; with size >= 0, exactly that many.
  // Entries are named "<path> entry <i>" (1-based).
  Eigen::VectorXd vector(const YAML::Node& node, const std::string& path,
                         Eigen::Index size = -1) const;
  // Nested row lists [[a, b], [c, d]] or (RowsOrDiag) {diag: [a, b]}; non-empty,
  // rectangular, every entry a finite number. Messages give 1-based (row, column).
  Eigen::MatrixXd matrix(const YAML::Node& node, const std::string& path,
                         MatrixForms forms = MatrixForms::RowsOrDiag) const;
  // A matrix entry read by the caller's rule instead of as a finite number (an expression
  // of named parameters, say): called with the entry's node, its path ("<path> entry (2, 1)",
  // "<path>.diag entry 2") and its 0-based row and column.
  using EntryReader = std::function<double(const YAML::Node& entry, const std::string& entry_path,
                                           Eigen::Index row, Eigen::Index col)>;
  Eigen::MatrixXd matrix(const YAML::Node& node, const std::string& path, const EntryReader& entry,
                         MatrixForms forms = MatrixForms::RowsOrDiag) const;
  // matrix() of exactly rows x cols: "<path>: expected a 3x6 matrix, got 2x6".
  Eigen::MatrixXd matrix(const YAML::Node& node, const std::string& path, Eigen::Index rows,
                         Eigen::Index cols, MatrixForms forms = MatrixForms::RowsOrDiag) const;

  // One item (a map) or a list of items: each node with its path, "<path>" for a single
  // map, "<path>[i]" (0-based) for the items of a list.
  std::vector<std::pair<YAML::Node, std::string>> one_or_list(const YAML::Node& node,
                                                              const std::string& path) const;

 private:
  std::string scalar_text(const YAML::Node& node, const std::string& path,
                          const char* expected) const;
  // "<source>:<line>:<col>" of a parser mark, or "<source>".
  std::string location_of(const YAML::Mark& mark) const;
  // fail() unless count ≤ kMaxMatrixDimension: "<path>: 30000 rows; ... at most 1000".
  void require_dimension(const YAML::Node& node, const std::string& path, const char* what,
                         size_t count) const;
  std::string source_;
};

// A map whose keys YamlReader::map has checked; its values are read by key with the
// key's full path. Without a fallback a key is required ("missing key 'truth.delta'");
// with one, an absent key gives the fallback. A key given with no value is not absent:
// it is refused as "an empty value".
class YamlMap {
 public:
  YamlMap(const YamlReader& reader, YAML::Node node, std::string path)
      : reader_(&reader), node_(std::move(node)), path_(std::move(path)) {}

  const YamlReader& reader() const { return *reader_; }
  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  std::string path_of(const std::string& key) const { return child_path(path_, key); }

  bool has(const std::string& key) const;
  // The value of `key`, an undefined node if absent.
  YAML::Node get(const std::string& key) const;
  // The value of `key`; absent: "missing key '<path.key>' (<what>)", at the map.
  YAML::Node required(const std::string& key, const std::string& what = "") const;

  // "<location of key's value, or of the map>: <path.key>: <what>".
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  // "<location>: <path.key> = <value>: <rule>".
  [[noreturn]] void fail_value(const std::string& key, double value, const std::string& rule) const;

  // The (required) sub-map at `key`.
  YamlMap map(const std::string& key, const std::vector<std::string>& allowed,
              EmptyMap empty = EmptyMap::Refused) const;

  double number(const std::string& key) const;  // may be non-finite
  double number(const std::string& key, double fallback) const;
  double finite(const std::string& key) const;
  double finite(const std::string& key, double fallback) const;
  double positive(const std::string& key) const;  // finite and > 0
  double positive(const std::string& key, double fallback) const;
  double nonnegative(const std::string& key) const;  // finite and >= 0
  double nonnegative(const std::string& key, double fallback) const;
  int integer(const std::string& key) const;
  int integer(const std::string& key, int fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string word(const std::string& key) const;
  std::string word(const std::string& key, const std::string& fallback) const;
  std::string choice(const std::string& key, const std::vector<std::string>& options) const;
  std::string choice(const std::string& key, const std::vector<std::string>& options,
                     const std::string& fallback) const;
  Eigen::VectorXd vector(const std::string& key, Eigen::Index size = -1) const;
  Eigen::MatrixXd matrix(const std::string& key, MatrixForms forms = MatrixForms::RowsOrDiag) const;
  Eigen::MatrixXd matrix(const std::string& key, Eigen::Index rows, Eigen::Index cols,
                         MatrixForms forms = MatrixForms::RowsOrDiag) const;

 private:
  const YamlReader* reader_;
  YAML::Node node_;
  std::string path_;
};

}  // namespace hinf
