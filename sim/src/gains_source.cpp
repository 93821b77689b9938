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

ObtainedGains obtain_gains(const LtiGainsSource& source, const StatusLog& log) {
  ObtainedGains out;
  if (!source.gains_path.empty()) {
    // read once: the bytes parsed are the bytes copied into the run directory
    out.gains_yaml = hinf::read_input_file(source.gains_path, "gains file", hinf::kMaxGainsBytes);
    const auto file = hinf::runtime_yaml::parse_gains_yaml(out.gains_yaml, source.gains_path);
    refuse_known_input(file.G_F.cols(), source.gains_path);
    out.gains = {file.A_F, file.B_F, file.C_F, file.D_F};
    out.gamma = file.gamma;
    out.origin = "gains file " + source.gains_path;
    return out;
  }
  auto config = hinf::synth::load_config(source.synthesize_path);
  if (log) log("synthesising from " + source.synthesize_path + " ...");
  const hinf::synth::SynthesisResult r = hinf::synth::synthesize(config.plant, config.settings);
  refuse_known_input(r.filter.G_F.cols(), source.synthesize_path);
  out.gains = {r.filter.A_F, r.filter.B_F, r.filter.C_F, r.filter.D_F};
  out.gamma = r.gamma;
  // The synthesis library's own writer: the same file `hinf-synth solve -o` writes.
  out.gains_yaml = hinf::synth::format_gains_yaml(r, {source.synthesize_path, config.sha256, config.sample_time()});
  out.origin = "synthesised from " + source.synthesize_path;
  return out;
}

}  // namespace hinf::sim
