// The solver's memory model (sdp/memory_model.hpp) against peak resident sizes measured
// with `/usr/bin/time -f %M build/bin/hinf-synth solve CONFIG -o g.yaml` on the random
// plants of scripts/bench-synth (random_config(n, 1); docs/benchmarks.md "Memory"). A
// guard that refuses what fits is a nuisance, one that admits what does not is a crash:
// the model must stay above every measured peak, and within 2.5× of it.
#include <gtest/gtest.h>

#include "hinf/sdp/memory_model.hpp"

namespace {

struct Measured {
  int n;
  long order, params;
  double peak_kb;  // /usr/bin/time %M
};

TEST(MemoryModel, BoundsTheMeasuredPeaksFromAbove) {
  // (order, params) from `hinf-synth export-sdpa` (bLOCKsTRUCT, mDIM), + 2 phase variables
  const Measured measured[] = {{6, 37, 130, 17544}, {10, 60, 344, 34216}, {16, 95, 868, 142696},
                               {24, 142, 1948, 387788}};
  for (const Measured& m : measured) {
    const double model = hinf::sdp::estimated_peak_bytes(m.order, m.params);
    const double peak = 1024.0 * m.peak_kb;
    EXPECT_GE(model, peak) << "n = " << m.n;
    EXPECT_LE(model, 2.5 * peak) << "n = " << m.n;
  }
}

TEST(MemoryModel, GrowsWithTheProblem) {
  EXPECT_LT(hinf::sdp::estimated_peak_bytes(60, 344), hinf::sdp::estimated_peak_bytes(95, 868));
  // n = 80 (order 468, 21362 variables): far beyond a 24 GiB machine
  EXPECT_GT(hinf::sdp::estimated_peak_bytes(468, 21364), 24.0 * (1u << 30));
}

}  // namespace
