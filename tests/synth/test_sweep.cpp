// Parameter studies (docs/maths.md §21): the range syntax, the in-place replacement of a
// config number, and the bisection for the largest certified uncertainty against the
// boundary s* = 1/‖E(zI − A)⁻¹H‖∞ of (135) computed independently (symplectic pencil).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hinf/certify/hinf_norm.hpp"
#include "hinf/common/error.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/sweep.hpp"
#include "bisection.hpp"

namespace {

using hinf::ErrorCode;
namespace synth = hinf::synth;

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

// The two-mass spring-damper of tests/data/plants with E written for δ̄ = 1, so that
// uncertainty_scale is δ̄ itself.
const char* const kTwoMass = R"(# two masses, coupling stiffness uncertain
system:
  A: [[0, 0, 1, 0], [0, 0, 0, 1], [-2, 1, -0.2, 0], [1, -1, 0, -0.2]]
  B: [[0, 0], [0, 0], [1, 0], [0, 1]]
  C: [[0, 1, 0, 0]]
  D: [[0.1]]
  L: [[1, 0, 0, 0], [0, 1, 0, 0]]
  sample_time: 0.05   # s
  discretisation: euler
uncertainty:
  H: [[0], [0], [-1], [1]]
  E: [[1, -1, 0, 0]]
)";

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

// The search's bisection stops at the tolerance, or at floating-point resolution when the
// tolerance is below it (issue 34: --tolerance 1e-300 never ended).
TEST(Sweep, BisectionStopsAtTheToleranceOrAtFloatingPointResolution) {
  const auto below = [](double v) { return v < 0.3; };
  double good = 0, bad = 1;
  EXPECT_EQ(synth::bisect(good, bad, 1e-3, below), 10);  // 2^-10 < 1e-3 < 2^-9
  EXPECT_LT(good, 0.3);
  EXPECT_GE(bad, 0.3);
  EXPECT_LE(bad - good, 1e-3);
  good = 0, bad = 1;
  const int n = synth::bisect(good, bad, 1e-300, below);
  EXPECT_LE(n, 60);  // about 54 halvings reach the spacing of doubles near 0.3
  EXPECT_LT(good, 0.3);
  EXPECT_GE(bad, 0.3);
  EXPECT_EQ(std::nextafter(good, 1.0), bad);  // adjacent doubles: nothing left to halve
  double high_good = 1, low_bad = 0;  // the bracket the other way round
  synth::bisect(high_good, low_bad, 1e-300, [](double v) { return v >= 0.3; });
  EXPECT_GE(high_good, 0.3);
  EXPECT_EQ(std::nextafter(low_bad, 1.0), high_good);
}

TEST(Sweep, RangesAreComputedFromTheirIndexAndBadOnesNamed) {
  const std::vector<double> v = synth::parse_sweep_range("0:0.05:1", "--param");
  ASSERT_EQ(v.size(), 21u);
  EXPECT_EQ(v.front(), 0.0);
  EXPECT_EQ(v[3], 3 * 0.05);
  EXPECT_EQ(v.back(), 20 * 0.05);
  EXPECT_EQ(synth::parse_sweep_range("0.25", "--param"), std::vector<double>{0.25});
  for (const char* bad : {"0:0:1", "1:0.1:0", "a:1:2", "0:1", "0:0.1:1:2", "0:nan:1", "0:1e-9:1", "0:0.1:1x",
                          "0x0:0.1:1", "0:0x1p-3:1", "0:0.1:inf"})  // one decimal form, as in the config
    EXPECT_HAS(error_of([&] { synth::parse_sweep_range(bad, "--param"); }), "--param '" + std::string(bad) + "'");
}

TEST(Sweep, AConfigNumberIsReplacedInPlaceAndOnlyThere) {
  const std::string text = synth::with_value(kTwoMass, "c.yaml", "system.sample_time", 0.025);
  std::string expected = kTwoMass;
  expected.replace(expected.find("0.05   # s"), 4, "0.025");
  EXPECT_EQ(text, expected);
  EXPECT_EQ(*synth::parse_config(text, "c.yaml").sample_time(), 0.025);
  EXPECT_HAS(error_of([] { synth::with_value(kTwoMass, "c.yaml", "system.sample_tme", 1); }), "'system.sample_tme'");
  EXPECT_HAS(error_of([] { synth::with_value(kTwoMass, "c.yaml", "system.A", 1); }), "'system.A' is not a plain number");
  EXPECT_HAS(error_of([] { synth::with_value(kTwoMass, "c.yaml", "system.discretisation", 1); }),
             "system.discretisation");
  EXPECT_HAS(error_of([] { synth::resolve_sweep_parameter("delta_bar", kTwoMass, "c.yaml"); }), "'hill.delta_bar'");
  const std::string certain = std::string(kTwoMass).substr(0, std::string(kTwoMass).find("uncertainty:"));
  EXPECT_HAS(error_of([&] { synth::resolve_sweep_parameter("uncertainty_scale", certain, "c.yaml"); }),
             "uncertainty_scale");
  const synth::SweepParameter s = synth::resolve_sweep_parameter("uncertainty_scale", kTwoMass, "c.yaml");
  EXPECT_EQ(synth::config_at(s, 0.05, kTwoMass, "c.yaml").plant.E(0, 1), -0.05);
  EXPECT_HAS(error_of([&] { synth::config_at(s, -1, kTwoMass, "c.yaml"); }), "uncertainty_scale = -1");
}

TEST(Sweep, TheLargestCertifiedUncertaintyBracketsTheBoundary) {
  const synth::SynthConfig cfg = synth::parse_config(kTwoMass, "c.yaml");
  const double boundary =
      1 / hinf::certify::discrete_hinf_norm(cfg.plant.A, cfg.plant.H, cfg.plant.E,
                                            Eigen::MatrixXd::Zero(cfg.plant.E.rows(), cfg.plant.H.cols()))
              .norm;
  EXPECT_NEAR(boundary, 0.0589879, 1e-7);  // the figure the data file's comment gives
  const synth::SweepParameter s = synth::resolve_sweep_parameter("uncertainty_scale", kTwoMass, "c.yaml");
  const synth::FeasibilitySearch r = synth::max_feasible(s, 0, 1, 1e-3, kTwoMass, "c.yaml");
  ASSERT_TRUE(r.bracketed);
  ASSERT_TRUE(r.smallest_infeasible);
  EXPECT_EQ(r.largest_certified.outcome, ErrorCode::Ok);
  EXPECT_LT(r.largest_certified.value, boundary);
  EXPECT_GT(r.smallest_infeasible->value, boundary);
  EXPECT_LE(r.smallest_infeasible->value - r.largest_certified.value, 1e-3);
  EXPECT_LE(r.width, 1e-3);
  for (const synth::SweepPoint& p : r.evaluated) {
    if (p.value < boundary) {
      EXPECT_NE(p.outcome, ErrorCode::Infeasible) << p.value;  // no false verdict
    } else {
      EXPECT_NE(p.outcome, ErrorCode::Ok) << p.value;  // no false certificate
    }
  }
}

TEST(Sweep, EveryGridPointBelowTheBoundaryIsCertifiedAndEveryOneAboveVerifiedInfeasible) {
  const synth::SweepParameter s = synth::resolve_sweep_parameter("uncertainty_scale", kTwoMass, "c.yaml");
  const std::vector<synth::SweepPoint> points =
      synth::sweep(s, synth::parse_sweep_range("0:0.01:0.8", "--param"), kTwoMass, "c.yaml");
  ASSERT_EQ(points.size(), 81u);
  for (const synth::SweepPoint& p : points)
    EXPECT_EQ(p.outcome, p.value < 0.0589879 ? ErrorCode::Ok : ErrorCode::Infeasible) << p.value << ": " << p.message;
  for (std::size_t i = 1; i < points.size() && points[i].outcome == ErrorCode::Ok; ++i)
    EXPECT_GT(points[i].gamma, points[i - 1].gamma * (1 - 1e-6));  // more uncertainty, no smaller bound
}

}  // namespace
