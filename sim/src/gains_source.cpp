#include "hinf/sim/gains_source.hpp"

#include <hinf/runtime_yaml/gains_file.hpp>
#include <hinf/synth/config.hpp>
#include <hinf/synth/gains_output.hpp>
#include <hinf/synth/synthesis.hpp>

#include <hinf/common/error.hpp>
#include <hinf/common/input_file.hpp>

namespace hinf::sim {
namespace {
// The scenarios feed the LTI filter y only; a filter that expects u would run without it.
void refuse_known_input(Eigen::Index r, const std::string& source) {
  if (r > 0)
    throw hinf::Error(hinf::ErrorCode::InvalidInput,
                      source + ": the filter has a known input (filter.G_F, r = " + std::to_string(r) +
                          "); hinf-sim feeds the H-infinity filter the measurement y only");
}
}  // namespace

ObtainedGains obtain_gains(const LtiGainsSource& source, const StatusLog& log, KnownInput known_input) {
  if (!source.gains_path.empty()) {
    ObtainedGains out;
    // read once: the bytes parsed are the bytes copied into the run directory
    out.gains_yaml = hinf::read_input_file(source.gains_path, "gains file", hinf::kMaxGainsBytes);
    const auto file = hinf::runtime_yaml::parse_gains_yaml(out.gains_yaml, source.gains_path);
    if (known_input == KnownInput::Refused) refuse_known_input(file.G_F.cols(), source.gains_path);
    out.gains = {file.A_F, file.B_F, file.C_F, file.D_F};
    out.gamma = file.gamma;
    out.origin = "gains file " + source.gains_path;
    return out;
  }
  const auto config = hinf::synth::load_config(source.synthesize_path);
  if (log) log("synthesising from " + source.synthesize_path + " ...");
  const hinf::synth::SynthesisResult r = hinf::synth::synthesize(config.plant, config.settings);
  if (known_input == KnownInput::Refused) refuse_known_input(r.filter.G_F.cols(), source.synthesize_path);
  return obtained_from(r, config, "synthesised from " + source.synthesize_path);
}

ObtainedGains obtained_from(const hinf::synth::SynthesisResult& result, const hinf::synth::SynthConfig& config,
                            const std::string& origin) {
  ObtainedGains out;
  out.gains = {result.filter.A_F, result.filter.B_F, result.filter.C_F, result.filter.D_F};
  out.gamma = result.gamma;
  // The synthesis library's own writer: the same file `hinf-synth solve -o` writes.
  out.gains_yaml = hinf::synth::format_gains_yaml(result, {config.path, config.sha256, config.sample_time()});
  out.origin = origin;
  return out;
}

}  // namespace hinf::sim
