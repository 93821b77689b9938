// What the scenario readers of sim/ share beyond common's YamlReader (private to sim/src).
#pragma once
#include <Eigen/Dense>

#include "hinf/common/yaml_reader.hpp"

namespace hinf::sim {

// A 3-vector under `key` (every entry finite) times `scale`, or `fallback` when absent.
inline Eigen::Vector3d scenario_vector3(const YamlMap& m, const char* key, const Eigen::Vector3d& fallback,
                                        double scale = 1.0) {
  if (!m.has(key)) return fallback;
  const Eigen::VectorXd v = m.vector(key, 3);
  if (!v.allFinite()) m.fail(key, "every entry must be finite");
  return v * scale;
}

}  // namespace hinf::sim
