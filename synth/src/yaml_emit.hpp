// The pieces the output files (gains_output.cpp, controller_output.cpp) are written with.
#pragma once
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <string>

namespace hinf::synth {

// key: [[row], [row], …], each row a flow sequence.
inline void emit_matrix(YAML::Emitter& out, const char* key, const Eigen::MatrixXd& M) {
  out << YAML::Key << key << YAML::Value << YAML::BeginSeq;
  for (int i = 0; i < M.rows(); ++i) {
    out << YAML::Flow << YAML::BeginSeq;
    for (int j = 0; j < M.cols(); ++j) out << M(i, j);
    out << YAML::EndSeq;
  }
  out << YAML::EndSeq;
}

template <class T>
void kv(YAML::Emitter& out, const char* key, const T& v) {
  out << YAML::Key << key << YAML::Value << v;
}

// The `timing:` section, last in every output file: the only bytes that differ between
// two runs of the same input.
inline void emit_timing(YAML::Emitter& out, double solve_time_s) {
  out << YAML::Key << "timing" << YAML::Value << YAML::BeginMap;
  kv(out, "solve_time_s", solve_time_s);
  out << YAML::EndMap;
}

inline std::string eigen_version() {
  return std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
         std::to_string(EIGEN_MINOR_VERSION);
}

}  // namespace hinf::synth
