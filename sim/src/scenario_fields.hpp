// What the scenario readers of sim/ share beyond common's YamlReader (private to sim/src).
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <string>

#include "hinf/common/number_text.hpp"
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

// The most samples a run may take (1e7: 116 days at 1 s).
constexpr double kMaxScenarioSamples = 1e7;

// `duration` (required, a whole multiple of `sample_time`, at most 1e7 samples), `sample_time`
// and `truth_substeps` (1…1000) of a sampled scenario; absent optional keys keep their value.
inline void read_sampled_timing(const YamlMap& top, double& duration, double& sample_time, int& truth_substeps) {
  top.required("duration", "s");
  duration = top.positive("duration");
  sample_time = top.positive("sample_time", sample_time);
  const double k = duration / sample_time;
  if (std::abs(k - std::round(k)) > 1e-9 * k || std::round(k) < 1)
    top.fail_value("duration", duration, "must be a whole multiple of sample_time " + number_text(sample_time));
  if (k > kMaxScenarioSamples) top.fail_value("duration", duration, "needs more than 1e7 samples");
  truth_substeps = top.integer("truth_substeps", truth_substeps);
  if (truth_substeps < 1 || truth_substeps > 1000) top.fail("truth_substeps", "must be in 1…1000");
}

}  // namespace hinf::sim
