// A filter beside the Kalman predictor (docs/maths.md §25): each filter wins in its own norm,
// and the σ(θ) curves never exceed the H∞ norms of the symplectic pencil, reaching them at
// the peaks added to the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hinf/synth/comparison.hpp"
#include "hinf/synth/config.hpp"

namespace {

namespace synth = hinf::synth;

void expect_curve_under_norm(const synth::FilterFigures& f) {
  const double top = *std::max_element(f.sigma.begin(), f.sigma.end());
  EXPECT_LE(top, f.hinf_norm_nominal * (1 + 1e-9));
  EXPECT_GE(top, f.hinf_norm_nominal * (1 - 1e-9));  // the peak frequency is on the grid
}

TEST(Comparison, EachFilterWinsInItsOwnNorm) {
  for (const char* name : {"/configs/paper-dbar0.05.yaml", "/configs/paper-no-control.yaml"}) {
    SCOPED_TRACE(name);
    const synth::SynthConfig cfg = synth::load_config(std::string(HINF_SOURCE_DIR) + name);
    const synth::SynthesisResult hinf = synth::synthesize(cfg.plant, cfg.settings);
    const synth::Comparison c = synth::compare_with_kalman(cfg.plant, hinf.filter, cfg.settings, 200);
    EXPECT_GE(c.theta.size(), 200u);
    EXPECT_TRUE(std::is_sorted(c.theta.begin(), c.theta.end()));
    EXPECT_LE(c.kalman.h2_norm_nominal, c.filter.h2_norm_nominal * (1 + 1e-9));      // Kalman: least RMS
    EXPECT_LE(c.filter.robust_bound, c.kalman.robust_bound * (1 + 1e-7));            // H∞: least worst case
    EXPECT_LE(c.filter.robust_bound, hinf.gamma * (1 + 1e-9));
    expect_curve_under_norm(c.filter);
    expect_curve_under_norm(c.kalman);
  }
}

}  // namespace
