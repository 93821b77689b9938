// libFuzzer harness: the SDPA writer (export-sdpa) on every plant the config reader
// accepts from arbitrary bytes: Theorem 1 as SDPA text, which must name every entry
// with a finite number. Plants above kMaxOrder states are skipped (the LMI grows as n²:
// a 1000-state diag plant from 4 KB of input would test memory, not the writer).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/synthesis.hpp"

namespace {
constexpr long kMaxOrder = 12;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  hinf::synth::SynthConfig config;
  try {
    config = hinf::synth::parse_config(text, "fuzz.yaml");
  } catch (const hinf::Error&) {
    return 0;
  }
  if (config.plant.n() > kMaxOrder) return 0;
  std::string sdpa;
  try {
    sdpa = hinf::synth::synthesis_sdpa(config.plant, config.settings, "fuzz");  // Theorem 1 or (124)
  } catch (const hinf::Error&) {
    return 0;
  }
  // every number of the file reads back finite (the writer's contract with CSDP)
  std::istringstream lines(sdpa);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '*') continue;
    std::istringstream words(line);
    for (std::string w; words >> w;) {
      char* end = nullptr;
      const double v = std::strtod(w.c_str(), &end);
      if (end != w.c_str() && !std::isfinite(v)) std::abort();
    }
  }
  return 0;
}
