// libFuzzer harness: the scenario readers (sim/: the Hill family, gps_ins_relative,
// gyroless_attitude and manoeuvring_target) on
// arbitrary bytes; see fuzz_config.cpp for
// what counts as a finding. Paths named in a scenario resolve against the working
// directory and are only tested for existence.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/sim/gps_ins_scenario_yaml.hpp"
#include "hinf/sim/gyroless_scenario_yaml.hpp"
#include "hinf/sim/hold_scenario_yaml.hpp"
#include "hinf/sim/manoeuvring_scenario_yaml.hpp"
#include "hinf/sim/scenario_yaml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const std::string family = hinf::sim::scenario_family(text, "fuzz.yaml");
    if (family == "gps_ins_relative")
      hinf::sim::parse_gps_ins_scenario(text, "fuzz.yaml");
    else if (family == "gyroless_attitude")
      hinf::sim::parse_gyroless_scenario(text, "fuzz.yaml");
    else if (family == "manoeuvring_target")
      hinf::sim::parse_manoeuvring_scenario(text, "fuzz.yaml");
    else
      hinf::sim::parse_scenario(text, "fuzz.yaml");
  } catch (const hinf::Error&) {
  }
  return 0;
}
