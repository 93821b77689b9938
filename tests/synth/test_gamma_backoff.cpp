// γ back-off (docs/maths.md §6, [D6]): the filter recovered at γ_b = (1 + b)·γ* from the point of
// largest LMI margin is certified at γ_b and is better conditioned than the γ*-optimal one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hinf/synth/config.hpp"
#include "hinf/synth/synthesis.hpp"

namespace {

TEST(GammaBackoff, PaperPlantCertifiedAtBackedOffGammaAndBetterConditioned) {
  const auto cfg = hinf::synth::load_config(std::string(HINF_SOURCE_DIR) + "/configs/paper-dbar0.05.yaml");
  hinf::synth::Settings s = cfg.settings;
  const auto opt = hinf::synth::synthesize(cfg.plant, s);
  s.gamma_backoff = 0.01;
  const auto bo = hinf::synth::synthesize(cfg.plant, s);
  ASSERT_TRUE(bo.certificate.passed);
  // same optimum found by both runs, and the written γ is the backed-off one
  EXPECT_NEAR(bo.solver.optimal_gamma, opt.gamma, 1e-7 * opt.gamma);
  EXPECT_NEAR(bo.gamma, 1.01 * bo.solver.optimal_gamma, 1e-9 * bo.gamma);
  // the filter's own bounds are certified below the written γ
  EXPECT_LE(bo.certificate.hinf_norm_nominal, bo.gamma);
  EXPECT_LE(bo.certificate.robust_bound, bo.gamma);
  // and it cannot beat the optimum
  EXPECT_GE(bo.certificate.robust_bound, opt.gamma * (1 - 1e-6));
  // larger margin: R − S better conditioned than at the γ-optimal point
  EXPECT_LT(bo.certificate.cond_R_minus_S, opt.certificate.cond_R_minus_S);
}

// A problem whose largest margin is tiny (~3e-6): the back-off solve must not ask for a
// relative accuracy on the margin that round-off cannot give (it used to fail, exit 4).
TEST(GammaBackoff, TinyMarginProblemStillSolves) {
  const auto cfg =
      hinf::synth::load_config(std::string(HINF_SOURCE_DIR) + "/configs/paper-no-control-discounted.yaml");
  hinf::synth::Settings s = cfg.settings;
  s.gamma_backoff = 0.01;
  const auto bo = hinf::synth::synthesize(cfg.plant, s);
  EXPECT_TRUE(bo.certificate.passed);
  EXPECT_NEAR(bo.gamma, 1.01 * bo.solver.optimal_gamma, 1e-9 * bo.gamma);
  EXPECT_LE(bo.certificate.robust_bound, bo.gamma);
}

}  // namespace
