// The registry of problem kinds (kinds.hpp): the kinds a config declares by its keys, in
// order — a new kind is one line here — and the filter kind for every config none of them
// declares (its reader then names what is wrong with it).
#include <array>

#include "hinf/synth/controller_config.hpp"
#include "kinds.hpp"

namespace hinf::synth {
namespace {

const ProblemKind& kind_of(const std::string& yaml_text) {
  static const std::array<const ProblemKind*, 1> declared = {&controller_kind()};
  for (const ProblemKind* kind : declared)
    if (kind->declares(yaml_text)) return *kind;
  return filter_kind();
}

}  // namespace

std::unique_ptr<Problem> parse_problem(const std::string& yaml_text, const std::string& source_name) {
  return kind_of(yaml_text).parse(yaml_text, source_name);
}

std::unique_ptr<Problem> load_problem(const std::string& path) { return parse_problem(read_config_bytes(path), path); }

std::optional<DiscretiseOutcome> discretise_for_codegen(const std::string& controller_path,
                                                        const std::string& config_path, std::optional<double> tustin,
                                                        std::optional<double> zoh) {
  if (tustin && zoh) throw Error(ErrorCode::InvalidInput, "--tustin and --zoh: give one discretisation", "tustin");
  if (!tustin && !zoh) {
    if (!config_path.empty())
      throw Error(ErrorCode::InvalidInput, "--config: only with --tustin or --zoh (a continuous-time controller "
                                           "discretised, its sampled loop certified)", "config");
    return std::nullopt;
  }
  const ControllerSampling method = tustin ? ControllerSampling::Tustin : ControllerSampling::ZeroOrderHold;
  const double period = tustin ? *tustin : *zoh;
  const std::string key = std::string("--") + to_string(method);
  require_sample_period(period, key);
  if (config_path.empty())
    throw Error(ErrorCode::InvalidInput, std::string("--") + to_string(method) + ": give --config CONFIG, the "
                "controller's config: the loop of the discretised controller is certified on its plant sampled at "
                "the same period", "config");
  return load_problem(config_path)->discretise(controller_path, period, method);
}

}  // namespace hinf::synth
