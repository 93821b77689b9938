// Strict, typed reading of yaml-cpp nodes for the config reader (docs/file-formats.md).
// Every failure throws Error(InvalidInput) "<source>:<line>:<col>: <key path>: <what>".
#pragma once
#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace hinf {

// "a.b" from ("a", "b"); "b" from ("", "b").
std::string child_path(const std::string& parent, const std::string& key);

class YamlReader {
 public:
  explicit YamlReader(std::string source) : source_(std::move(source)) {}

  const std::string& source() const { return source_; }

  // "<source>:<line>:<col>" of a node (1-based), or "<source>" if it has no mark.
  std::string location(const YAML::Node& node) const;

  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const;

  // `node` must be a non-empty map whose keys are distinct plain scalars from `allowed`;
  // an unknown key is reported with its full path and the closest allowed key.
  void check_map(const YAML::Node& node, const std::string& path,
                 const std::vector<std::string>& allowed) const;

  // A plain scalar read as a YAML 1.2 core-schema float (also .inf, .nan); may be
  // non-finite, the caller's range check says why that is wrong.
  double number(const YAML::Node& node, const std::string& path) const;
  // A decimal integer in the range of int / unsigned.
  int integer(const YAML::Node& node, const std::string& path) const;
  unsigned unsigned_integer(const YAML::Node& node, const std::string& path) const;
  // true / false (YAML 1.2 core: also True, TRUE, False, FALSE).
  bool boolean(const YAML::Node& node, const std::string& path) const;
  // A plain or quoted scalar string.
  std::string word(const YAML::Node& node, const std::string& path) const;

  // Nested row lists [[a, b], [c, d]] or {diag: [a, b]}; non-empty, rectangular,
  // every entry a finite number. Messages give 1-based (row, column) positions.
  Eigen::MatrixXd matrix(const YAML::Node& node, const std::string& path) const;

 private:
  std::string scalar_text(const YAML::Node& node, const std::string& path,
                          const char* expected) const;
  std::string source_;
};

}  // namespace hinf
