// libFuzzer harness: the gains-file reader (runtime/yaml) on arbitrary bytes; see
// fuzz_config.cpp for what counts as a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    hinf::runtime_yaml::parse_gains_yaml(text, "fuzz.yaml");
  } catch (const hinf::Error&) {
  }
  return 0;
}
