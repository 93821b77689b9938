// load_config: reading a config file's exact bytes (their SHA-256 goes into the output).
#include "hinf/common/error.hpp"
#include "hinf/common/input_file.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/controller_config.hpp"

namespace hinf::synth {

std::string read_config_bytes(const std::string& path) {
  const std::string bytes = read_input_file(path, "config", kMaxConfigBytes);
  if (bytes.empty()) throw Error(ErrorCode::InvalidInput, path + ": empty config file (0 bytes)");
  return bytes;
}

SynthConfig load_config(const std::string& path) { return parse_config(read_config_bytes(path), path); }

}  // namespace hinf::synth
