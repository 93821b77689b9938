// libFuzzer harness: the scenario readers of every experiment family (sim/family.hpp: the
// registry picks the family by the `scenario:` key, its parse() reads and validates without
// running) on arbitrary bytes; see fuzz_config.cpp for what counts as a finding. Paths named
// in a scenario resolve against the working directory and are only tested for existence.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/sim/family.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    hinf::sim::family_of(text, "fuzz.yaml").parse(text, "fuzz.yaml");
  } catch (const hinf::Error&) {
  }
  return 0;
}
