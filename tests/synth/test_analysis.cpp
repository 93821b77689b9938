// analyze on filters that are not stable: a mode on the unit circle is a finding (ρ = 1, an
// unbounded norm), never an error. The filter below (example-matrices' plant; A_F with an
// eigenvalue at exactly 1, B_F and C_F of its synthesised filter) made `hinf-synth analyze`
// exit 3 with "discrete_hinf_norm: A is not Schur stable (spectral radius
// 1.0000000000000018 >= 1)": the norm computed the poles unbalanced, analyze's stability
// test balanced, and round-off put them on either side of 1.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/synth/analysis.hpp"
#include "hinf/synth/config.hpp"

namespace {

TEST(Analysis, ModeOnTheUnitCircleIsAFindingNotAnError) {
  const auto cfg = hinf::synth::load_config(std::string(HINF_SOURCE_DIR) + "/configs/example-matrices.yaml");
  Eigen::MatrixXd A_F(2, 2), B_F(2, 1), C_F(2, 2);
  A_F << 1, 0, 0, 0.5;
  B_F << -0.91345679659806667, -0.16303145236398434;
  C_F << -0.99999999746208545, 1.8585267371589489e-08, 9.0924242041084529e-10, -0.99999999076894897;
  const hinf::Filter filter(A_F, B_F, C_F);
  const hinf::synth::FilterAnalysis a = hinf::synth::analyze_filter(cfg.plant, cfg.hill, filter, cfg.settings, 0);
  EXPECT_NEAR(a.spectral_radius_nominal, 1.0, 1e-12);
  EXPECT_GT(a.hinf_norm_nominal, 1e12);  // +inf, or the pole's peak at θ = 0 if round-off put ρ below 1
  EXPECT_EQ(a.robust_bound, INFINITY);
}

}  // namespace

namespace {

// A nilpotent plant without uncertainty (A = [0 1; 0 0]) and its synthesised filter: the
// analysis LMI (50) failed on round-off at the end of its path (exit 4). Without
// uncertainty the robust bound is the nominal norm, computed by the pencil, and it lies
// between the norm and the γ the synthesis certified.
TEST(Analysis, BoundOfACertainPlantIsItsNominalNorm) {
  const std::string dir = std::string(HINF_SOURCE_DIR) + "/tests/data/analyze/";
  const auto cfg = hinf::synth::load_config(dir + "nilpotent-plant.yaml");
  const hinf::runtime_yaml::GainsFile g = hinf::runtime_yaml::load_gains_file(dir + "nilpotent-plant-gains.yaml");
  const hinf::Filter filter(g.A_F, g.B_F, g.C_F);
  const hinf::synth::FilterAnalysis a = hinf::synth::analyze_filter(cfg.plant, cfg.hill, filter, cfg.settings, 0);
  EXPECT_DOUBLE_EQ(a.robust_bound, a.hinf_norm_nominal);  // the pencil's certified value
  EXPECT_LE(a.robust_bound, *g.gamma);
  // x₁(k) = w(k − 1), which no predictor has seen (z_F(k) uses y up to k − 1): the gain
  // from w to e is at least 1 for every filter
  EXPECT_GE(a.robust_bound, 1.0);
}

}  // namespace
