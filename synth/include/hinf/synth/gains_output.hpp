// The gains file as text (docs/file-formats.md, format hinf-gains/1); hinf/common/atomic_file.hpp writes it.
#pragma once
#include <optional>
#include <string>

#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

struct GainsProvenance {
  std::string config_path;    // as given on the command line (informational)
  std::string config_sha256;  // of the config's bytes
  std::optional<double> sample_time;  // the filter's call period, s, if the config states it
};

// The gains file as text. Deterministic: same result → same bytes, except the
// `timing:` section (last in the file).
std::string format_gains_yaml(const SynthesisResult& result, const GainsProvenance& provenance);

// The file's `certificate:` section alone, a YAML document of one key (verify's JSON).
std::string certificate_yaml(const Certificate& certificate, FilterForm form);

const char* tool_version();

}  // namespace hinf::synth
