// The check/verify policies (synth/regression.hpp) called directly, on the example config:
// another realisation of the same filter is the same result, a changed γ is not; a
// claimed γ below what the filter achieves is refused with the achieved bound.
#include <gtest/gtest.h>

#include <string>

#include "hinf/synth/config.hpp"
#include "hinf/synth/regression.hpp"
#include "hinf/synth/synthesis.hpp"

namespace {

using Eigen::MatrixXd;

struct Solved {
  hinf::synth::SynthConfig config;
  hinf::synth::SynthesisResult result;
};

const Solved& example() {
  static const Solved s = [] {
    Solved out;
    out.config = hinf::synth::load_config(std::string(HINF_SOURCE_DIR) + "/configs/example-matrices.yaml");
    out.result = hinf::synth::synthesize(out.config.plant, out.config.settings);
    return out;
  }();
  return s;
}

// (T A_F T⁻¹, T B_F, C_F T⁻¹): the same transfer function in other coordinates.
hinf::Filter other_realisation(const hinf::Filter& f) {
  const int n = static_cast<int>(f.A_F.rows());
  MatrixXd T = MatrixXd::Identity(n, n);
  for (int i = 0; i < n; ++i) T(i, (i + 1) % n) += 0.5 * (i + 1);
  T.diagonal() *= 3.0;
  const MatrixXd Ti = T.inverse();
  hinf::Filter g = f;
  g.A_F = T * f.A_F * Ti;
  g.B_F = T * f.B_F;
  g.C_F = f.C_F * Ti;
  return g;
}

TEST(RegressionPolicy, AnotherRealisationIsTheSameResult) {
  const Solved& s = example();
  const hinf::synth::GoldenComparison c = hinf::synth::compare_with_golden(
      s.config, other_realisation(s.result.filter), s.result.gamma, s.result, 1e-6);
  EXPECT_TRUE(c.same_gamma);
  EXPECT_LE(c.filter_difference.relative, 1e-9);
  EXPECT_TRUE(c.same_filter);
  EXPECT_FALSE(c.golden_recertified.has_value());  // no need: the transfer functions agree
  EXPECT_TRUE(c.same());
}

TEST(RegressionPolicy, AChangedGammaIsNotTheSameResult) {
  const Solved& s = example();
  const hinf::synth::GoldenComparison c =
      hinf::synth::compare_with_golden(s.config, s.result.filter, 1.01 * s.result.gamma, s.result, 1e-6);
  EXPECT_FALSE(c.same_gamma);
  EXPECT_NEAR(c.gamma_relative_change, 1 - 1 / 1.01, 1e-12);
  EXPECT_FALSE(c.same());
}

TEST(RegressionPolicy, VerifyAcceptsTheWrittenGammaAndRefusesALowerOne) {
  const Solved& s = example();
  const hinf::synth::Verification ok = hinf::synth::verify_gains(s.config, s.result.filter, s.result.gamma);
  EXPECT_TRUE(ok.holds);
  EXPECT_FALSE(ok.achieved_bound.has_value());
  const hinf::synth::Verification low = hinf::synth::verify_gains(s.config, s.result.filter, 0.9 * s.result.gamma);
  EXPECT_FALSE(low.holds);
  ASSERT_TRUE(low.achieved_bound.has_value()) << low.achieved_unknown_reason;
  // The filter is optimal at γ: what it achieves lies between the refused claim and γ.
  EXPECT_GT(*low.achieved_bound, 0.9 * s.result.gamma);
  EXPECT_LE(*low.achieved_bound, s.result.gamma * (1 + 1e-5));
}

}  // namespace
