// libFuzzer harness: the config readers of every problem kind (synth/src/config), through
// the synthesis API's registry (hinf/synth/api.hpp: the kind the text declares) on arbitrary bytes. Every input
// must end as a parsed config or a hinf::Error (exit 2 in hinf-synth); anything else — a
// crash, a sanitizer report, another exception, a hang, memory beyond -rss_limit_mb — is a
// finding. scripts/fuzz runs it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/synth/api.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    hinf::synth::parse_problem(text, "fuzz.yaml");
  } catch (const hinf::Error&) {
  }
  return 0;
}
