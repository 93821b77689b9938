// What the scenario readers of sim/ share beyond common's YamlReader (private to sim/src).
#pragma once
#include <Eigen/Dense>

#include <cctype>
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

// The range of a standard deviation in SI: its square, the variance the filters' covariances
// and the noise generators use, is then a finite normal double (1e-300 … 1e300), so no
// covariance built from it overflows, or underflows to a singular matrix that a filter would
// refuse with a message naming its own class instead of the scenario's key.
constexpr double kMinStandardDeviation = 1e-150, kMaxStandardDeviation = 1e150;

enum class ZeroSigma { Refused, Allowed };  // Allowed: 0 means no such noise

// A standard deviation under `key`, in the file's unit (`fallback` when absent): finite,
// positive (or 0 where allowed), and times `to_si` within [kMinStandardDeviation,
// kMaxStandardDeviation]; else Error(InvalidInput) naming the key and value.
inline double standard_deviation(const YamlMap& m, const char* key, double fallback, double to_si, ZeroSigma zero) {
  if (!m.has(key)) return fallback;
  const double v = zero == ZeroSigma::Allowed ? m.nonnegative(key) : m.positive(key);
  const double si = v * to_si;
  const bool no_noise = zero == ZeroSigma::Allowed && v == 0;
  if (!(no_noise || (si >= kMinStandardDeviation && si <= kMaxStandardDeviation)))
    m.fail_value(key, v,
                 "a standard deviation must lie in [" + number_text(kMinStandardDeviation) + ", " +
                     number_text(kMaxStandardDeviation) + "] in SI units: its square is the variance the filters use");
  return v;
}

// A name that labels columns and plots: a-z, 0-9 and _ only, not empty; `what` says what it
// names ("a filter's name").
inline void require_column_name(const YamlMap& m, const std::string& name, const char* what) {
  bool ok = !name.empty();
  for (char c : name)
    ok = ok && (std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_');
  if (!ok) m.fail(name, std::string(what) + " may hold only a-z, 0-9 and _ (it names columns and plots)");
}

// The required map `filters` of filter names to settings, 1…max_filters entries; read(filters,
// name) for each, in the file's order. `examples` names a few types for the message.
template <class Read>
void read_named_filters(const YamlMap& top, std::size_t max_filters, const std::string& examples, const Read& read) {
  top.required("filters", "a map of filter names to settings (" + examples + ")");
  const YAML::Node node = top.get("filters");
  if (!node.IsMap() || node.size() == 0)
    top.reader().fail(node, "filters: must be a non-empty map of filter names to settings");
  if (node.size() > max_filters)
    top.reader().fail(node, "filters: at most " + std::to_string(max_filters) + " filters");
  const YamlMap filters(top.reader(), node, top.path_of("filters"));
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) top.reader().fail(kv.first, "filters: a filter's name must be a word");
    read(filters, kv.first.Scalar());
  }
}

// The most samples a run may take (1e7: 116 days at 1 s).
constexpr double kMaxScenarioSamples = 1e7;

// `duration` (at the map `top`) a whole multiple of `sample_time`, 1 … 1e7 samples.
inline void require_whole_samples(const YamlMap& top, double duration, double sample_time) {
  const double k = duration / sample_time;
  if (std::abs(k - std::round(k)) > 1e-9 * k || std::round(k) < 1)
    top.fail_value("duration", duration, "must be a whole multiple of sample_time " + number_text(sample_time));
  if (k > kMaxScenarioSamples) top.fail_value("duration", duration, "needs more than 1e7 samples");
}

// `duration` (required, a whole multiple of `sample_time`, at most 1e7 samples), `sample_time`
// and `truth_substeps` (1…1000) of a sampled scenario; absent optional keys keep their value.
inline void read_sampled_timing(const YamlMap& top, double& duration, double& sample_time, int& truth_substeps) {
  top.required("duration", "s");
  duration = top.positive("duration");
  sample_time = top.positive("sample_time", sample_time);
  require_whole_samples(top, duration, sample_time);
  truth_substeps = top.integer("truth_substeps", truth_substeps);
  if (truth_substeps < 1 || truth_substeps > 1000) top.fail("truth_substeps", "must be in 1…1000");
}

}  // namespace hinf::sim
