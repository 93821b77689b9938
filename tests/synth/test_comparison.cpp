// A filter beside the Kalman predictor (docs/maths.md §25): each filter wins in its own norm,
// and the σ(θ) curves never exceed the H∞ norms of the symplectic pencil, reaching them at
// the peaks added to the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hinf/synth/comparison.hpp"
#include "hinf/common/error.hpp"
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

// The Kalman predictor's covariances given in the config (kalman: {Q, R}): BBᵀ and DDᵀ
// written out give the default predictor; scaling both by 4 leaves the gain unchanged (the
// DARE is homogeneous); a larger R gives a smaller gain; bad matrices are named.
TEST(Comparison, KalmanCovariancesFromTheConfig) {
  const std::string base = "system:\n  A: [[1, 0.1], [0, 1]]\n  B: [[0.005], [0.1]]\n  C: [[1, 0]]\n  D: [[0.5]]\n"
                           "  L: [[1, 0], [0, 1]]\n";
  const synth::SynthConfig plain = synth::parse_config(base, "k.yaml");
  const Eigen::MatrixXd K0 = synth::kalman_predictor(plain.plant, plain.settings).filter.K;
  const synth::SynthConfig same =
      synth::parse_config(base + "kalman:\n  Q: [[2.5e-5, 5e-4], [5e-4, 0.01]]\n  R: [[0.25]]\n", "k.yaml");
  EXPECT_LT((synth::kalman_predictor(same.plant, same.settings, same.kalman_noise).filter.K - K0).norm(),
            1e-12 * K0.norm());
  const synth::SynthConfig scaled =
      synth::parse_config(base + "kalman:\n  Q: [[1e-4, 2e-3], [2e-3, 0.04]]\n  R: [[1]]\n", "k.yaml");
  EXPECT_LT((synth::kalman_predictor(scaled.plant, scaled.settings, scaled.kalman_noise).filter.K - K0).norm(),
            1e-10 * K0.norm());
  const synth::SynthConfig noisier = synth::parse_config(base + "kalman: {R: [[25]]}\n", "k.yaml");
  const synth::SynthesisResult kn = synth::kalman_predictor(noisier.plant, noisier.settings, noisier.kalman_noise);
  EXPECT_LT(kn.filter.K.norm(), K0.norm());
  EXPECT_TRUE(kn.certificate.passed);  // certified on the plant itself
  for (const auto& [bad, key] : std::vector<std::pair<std::string, std::string>>{
           {"kalman: {Q: [[1, 2], [0, 1]]}", "kalman.Q: not symmetric"},
           {"kalman: {Q: [[1, 0], [0, -1]]}", "kalman.Q: not positive semidefinite"},
           {"kalman: {R: [[0]]}", "kalman.R: not positive definite"},
           {"kalman: {R: [[1, 0], [0, 1]]}", "kalman.R: expected 1x1"},
           {"kalman: {P: [[1]]}", "kalman.P"}}) {
    try {
      synth::parse_config(base + bad + "\n", "k.yaml");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const hinf::Error& e) {
      EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

}  // namespace
