// analyze on filters that are not stable: a mode on the unit circle is a finding (ρ = 1, an
// unbounded norm), never an error. The filter below (example-matrices' plant; A_F with an
// eigenvalue at exactly 1, B_F and C_F of its synthesised filter) made `hinf-synth analyze`
// exit 3 with "discrete_hinf_norm: A is not Schur stable (spectral radius
// 1.0000000000000018 >= 1)": the norm computed the poles unbalanced, analyze's stability
// test balanced, and round-off put them on either side of 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"
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
  const hinf::synth::FilterAnalysis a = hinf::synth::analyze_filter(cfg.plant, cfg.hill, cfg.parameter_blocks, filter, cfg.settings, 0);
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
  const hinf::synth::FilterAnalysis a = hinf::synth::analyze_filter(cfg.plant, cfg.hill, cfg.parameter_blocks, filter, cfg.settings, 0);
  EXPECT_DOUBLE_EQ(a.robust_bound, a.hinf_norm_nominal);  // the pencil's certified value
  EXPECT_LE(a.robust_bound, *g.gamma);
  // x₁(k) = w(k − 1), which no predictor has seen (z_F(k) uses y up to k − 1): the gain
  // from w to e is at least 1 for every filter
  EXPECT_GE(a.robust_bound, 1.0);
}

}  // namespace

namespace {

// Two named parameters, one off-centre (docs/maths.md §22): the worst case over their box is
// reported in their units, inside their ranges; it is at least as bad as a 41 × 41 grid of
// the plant written by hand at each (k, c) (the error norm by the pencil), it is the norm at the
// values it names, and the robust bound lies above it.
TEST(Analysis, TheWorstCaseOverNamedParametersIsNamedInTheirUnits) {
  const std::string text = R"(parameters:
  k: {nominal: 1, range: [0.97, 1.05]}
  c: {nominal: 0.2, range: [0.195, 0.21]}
system:
  A: [[0, 0, 1, 0], [0, 0, 0, 1], [-1 - k, k, -c, 0], [k, -k, 0, -c]]
  B: [[0, 0], [0, 0], [1, 0], [0, 1]]
  C: [[0, 1, 0, 0]]
  D: [[0.1]]
  L: [[1, 0, 0, 0], [0, 1, 0, 0]]
  sample_time: 0.05
  discretisation: euler
)";
  const auto cfg = hinf::synth::parse_config(text, "two-parameters.yaml");
  const hinf::synth::SynthesisResult r = hinf::synth::synthesize(cfg.plant, cfg.settings);
  const hinf::synth::FilterAnalysis a =
      hinf::synth::analyze_filter(cfg.plant, cfg.hill, cfg.parameter_blocks, r.filter, cfg.settings, 0);
  ASSERT_EQ(a.worst_parameters.size(), 2u);
  EXPECT_EQ(a.worst_parameters[0].name, "k");
  EXPECT_EQ(a.worst_parameters[1].name, "c");
  const double k = a.worst_parameters[0].value, c = a.worst_parameters[1].value;
  EXPECT_TRUE(k >= 0.97 && k <= 1.05 && c >= 0.195 && c <= 0.21) << k << " " << c;
  const auto norm_at = [&](double kk, double cc) {
    Eigen::Matrix4d Ac;
    Ac << 0, 0, 1, 0, 0, 0, 0, 1, -1 - kk, kk, -cc, 0, kk, -kk, 0, -cc;
    hinf::Plant p = cfg.plant;
    p.A = Eigen::Matrix4d::Identity() + 0.05 * Ac;
    p.H.resize(4, 0);
    p.E.resize(0, 4);
    p.F_blocks.clear();
    return hinf::certify::discrete_hinf_norm(hinf::certify::error_system(p, r.filter), 1e-10).norm;
  };
  double grid_max = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) grid_max = std::max(grid_max, norm_at(0.97 + 0.002 * i, 0.195 + 0.000375 * j));
  EXPECT_GE(a.worst_parameters_gain, grid_max * (1 - 1e-7)) << "grid " << grid_max;
  EXPECT_NEAR(a.worst_parameters_gain, norm_at(k, c), 1e-7 * grid_max);
  EXPECT_LE(a.worst_parameters_gain, a.robust_bound);
  EXPECT_LE(a.worst_parameters_gain, r.gamma);
}

}  // namespace
