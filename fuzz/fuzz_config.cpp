// libFuzzer harness: the config readers (synth/src/config: a filter config, or a controller
// config when the text declares `controller:`) on arbitrary bytes. Every input
// must end as a parsed config or a hinf::Error (exit 2 in hinf-synth); anything else — a
// crash, a sanitizer report, another exception, a hang, memory beyond -rss_limit_mb — is a
// finding. scripts/fuzz runs it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/controller_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    if (hinf::synth::declares_controller(text)) hinf::synth::parse_controller_config(text, "fuzz.yaml");
    else hinf::synth::parse_config(text, "fuzz.yaml");
  } catch (const hinf::Error&) {
  }
  return 0;
}
