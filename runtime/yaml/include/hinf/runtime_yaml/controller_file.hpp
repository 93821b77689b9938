// Reading a controller file (docs/file-formats.md, format hinf-controller/1) with the
// project's strict YAML reader: the controller (146) to fly, its time domain and period.
// Every failure is hinf::Error(InvalidInput) naming the file, position, key path and sizes.
#pragma once
#include <Eigen/Dense>
#include <optional>
#include <string>

namespace hinf::runtime_yaml {

// A discrete controller made from a continuous one (`hinf-synth codegen --tustin/--zoh`,
// docs/maths.md (161)–(161c)): how, and the continuous loop's γ; its own `gamma` is the
// sampled loop's, on the config's plant sampled at sample_time by a zero-order hold.
struct Discretised {
  std::string method;                     // tustin | zoh
  std::optional<double> continuous_gamma;  // the continuous-time file's γ
};

struct ControllerFile {
  bool discrete = false;              // time: discrete (else continuous)
  std::optional<double> sample_time;  // s, discrete time only (required there)
  std::optional<double> gamma;
  std::string tool, config_sha256;
  Eigen::MatrixXd A_K, B_K, C_K, D_K;  // n_K×n_K, n_K×ny, nu×n_K, nu×ny
  std::optional<Discretised> discretised;  // discrete-time files only
};

ControllerFile parse_controller_yaml(const std::string& text, const std::string& source_name);
ControllerFile load_controller_file(const std::string& path);

}  // namespace hinf::runtime_yaml
