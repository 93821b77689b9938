// Reading a gains file (docs/file-formats.md, format hinf-gains/1).
#pragma once
#include <Eigen/Dense>
#include <optional>
#include <stdexcept>
#include <string>

namespace hinf::runtime_yaml {

struct GainsFile {
  Eigen::MatrixXd A_F, B_F, C_F;      // SPEC eq. (12)
  std::optional<double> gamma;        // certified bound, if the file has one
  std::string config_sha256;          // empty if absent
  std::string tool;                   // empty if absent
};

// Thrown for any unreadable or invalid gains file; the message names the file,
// the key and (for matrices) the expected and actual dimensions.
class GainsFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

GainsFile load_gains_file(const std::string& path);
GainsFile parse_gains_yaml(const std::string& text, const std::string& source_name);

}  // namespace hinf::runtime_yaml
