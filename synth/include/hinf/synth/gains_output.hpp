// Writing a gains file (docs/file-formats.md, format hinf-gains/1) and atomic file output.
#pragma once
#include <string>

#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

struct GainsProvenance {
  std::string config_path;    // as given on the command line (informational)
  std::string config_sha256;  // of the config's bytes
};

// The gains file as text. Deterministic: same result → same bytes, except the
// `timing:` section (last in the file).
std::string format_gains_yaml(const SynthesisResult& result, const GainsProvenance& provenance);

// Writes `text` to `path` atomically (temporary file in the same directory, then
// rename). Throws Error(InvalidInput) naming the path and the reason; never leaves a
// partial file.
void write_file_atomically(const std::string& path, const std::string& text);

const char* tool_version();

}  // namespace hinf::synth
