// Reading a gains file (docs/file-formats.md, format hinf-gains/1).
#pragma once
#include <Eigen/Dense>
#include <optional>
#include <string>

#include "hinf/common/error.hpp"

namespace hinf::runtime_yaml {

struct GainsFile {
  Eigen::MatrixXd A_F, B_F, C_F;      // docs/maths.md (5)-(6)
  bool observer_form = false;         // filter.form: observer (absent or augmented: false)
  Eigen::MatrixXd K;                  // filter.K, n×m (observer form only)
  Eigen::MatrixXd G_F;                // filter.G_F, n×r known input (n×0 if absent)
  bool filtered = false;              // filter.estimate: filtered (observer form, docs/maths.md §18.6)
  Eigen::MatrixXd M;                  // filter.M, n×m: x̂(k|k) = x̂ + M (y − C x̂) (filtered only)
  Eigen::MatrixXd D_F;                // filter.D_F, l×m: z_F = C_F x_F + D_F y (filtered only; else empty)
  std::optional<double> gamma;        // certified bound, if the file has one
  std::optional<double> sample_time;  // s, the period the filter must be called at, if stated
  std::string config_sha256;          // empty if absent
  std::string tool;                   // empty if absent
};

// Any unreadable or invalid gains file throws hinf::Error (hinf/common/error.hpp) with
// ErrorCode::InvalidInput (exit code 2); the message names the file, the position
// (file:line:col), the key path and (for matrices) the expected and actual dimensions.
GainsFile load_gains_file(const std::string& path);
GainsFile parse_gains_yaml(const std::string& text, const std::string& source_name);

}  // namespace hinf::runtime_yaml
