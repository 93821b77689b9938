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
filter: {form: augmented}   # Theorem 1's boundary (135); form auto goes on to the observer form
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


// The two-mass plant with the coupling stiffness k named (docs/maths.md §22), and the same
// plant written with k's numbers by hand: a sweep by the parameter's name (§21) must give the
// hand-written plant, nominal and range moved to the value in k's units.
std::string two_mass_with_k(const std::string& parameter_line, const std::string& k) {
  return "constants: {c: 0.2}\n" + parameter_line +
         "system:\n"
         "  A: [[0, 0, 1, 0], [0, 0, 0, 1], [-1 - " + k + ", " + k + ", -c, 0], [" + k + ", -" + k + ", 0, -c]]\n"
         "  B: [[0, 0], [0, 0], [1, 0], [0, 1]]\n"
         "  C: [[0, 1, 0, 0]]\n"
         "  D: [[0.1]]\n"
         "  L: [[1, 0, 0, 0], [0, 1, 0, 0]]\n"
         "  sample_time: 0.05\n"
         "  discretisation: euler\n";
}

void expect_same_plant(const synth::SynthConfig& a, const synth::SynthConfig& b) {
  EXPECT_TRUE(a.plant.A.isApprox(b.plant.A, 1e-14)) << a.plant.A << "\n\n" << b.plant.A;
  EXPECT_TRUE(a.plant.H.isApprox(b.plant.H, 1e-14) && a.plant.E.isApprox(b.plant.E, 1e-14))
      << a.plant.H << "\n" << a.plant.E << "\n\n" << b.plant.H << "\n" << b.plant.E;
}

TEST(Sweep, ANamedParameterIsSweptInItsOwnUnitsWithItsRangeMovedAlong) {
  const std::string named = two_mass_with_k("parameters:\n  k: {nominal: 1, range: [0.9, 1.2]}\n", "k");
  const synth::SweepParameter k = synth::resolve_sweep_parameter("k", named, "c.yaml");
  EXPECT_EQ(k.kind, synth::SweepParameter::Kind::NamedParameter);
  // k = 1.5: nominal 1.5, range [1.4, 1.7] (offsets −0.1, +0.2 kept), in the text only there.
  const std::string moved = synth::with_parameter_value(named, "c.yaml", "k", 1.5);
  EXPECT_EQ(moved.substr(moved.find("system:")), named.substr(named.find("system:")));
  expect_same_plant(synth::config_at(k, 1.5, named, "c.yaml"),
                    synth::parse_config(two_mass_with_k("parameters:\n  k: {nominal: 1.5, range: [1.4, 1.7]}\n", "k"),
                                        "hand.yaml"));
  // The nominal plant is A(k) with k's number written in: the design point is the value.
  const synth::SynthConfig at2 = synth::config_at(k, 2, named, "c.yaml");
  const synth::SynthConfig by_hand = synth::parse_config(two_mass_with_k("", "2"), "hand.yaml");
  EXPECT_TRUE(at2.plant.A.isApprox(by_hand.plant.A, 1e-15)) << at2.plant.A;
  // Without a nominal the range's centre is the design point: it moves to the value.
  const std::string centred = two_mass_with_k("parameters:\n  k:\n    range: [0.9, 1.1]\n", "k");
  expect_same_plant(synth::config_at(synth::resolve_sweep_parameter("k", centred, "c.yaml"), 3, centred, "c.yaml"),
                    synth::parse_config(two_mass_with_k("parameters:\n  k: {range: [2.9, 3.1]}\n", "k"), "hand.yaml"));
}

TEST(Sweep, AParameterNameThatIsNotOneIsNamedWithTheClosest) {
  const std::string named = two_mass_with_k("parameters:\n  k: {nominal: 1, range: [0.9, 1.2]}\n", "k");
  EXPECT_HAS(error_of([&] { synth::resolve_sweep_parameter("kk", named, "c.yaml"); }), "did you mean 'k'?");
  EXPECT_HAS(error_of([&] { synth::resolve_sweep_parameter("zeta", named, "c.yaml"); }), "its parameters: k");
  const std::string quoted = two_mass_with_k("parameters:\n  k: {nominal: 1, range: ['0.9', 1.2]}\n", "k");
  EXPECT_HAS(error_of([&] { synth::resolve_sweep_parameter("k", quoted, "c.yaml"); }),
             "'parameters.k.range' is not a plain number");
  // A number that is a YAML anchor is read elsewhere through its aliases: replacing it in the
  // text would move those too (another parameter's nominal, the other end of the range), so
  // it is not a plain number to sweep.
  const std::string aliased = two_mass_with_k("parameters:\n  k: {nominal: &n 1, range: [0.9, 1.2]}\n"
                                              "  m: {nominal: *n, range: [0.5, 1.5]}\n", "k");
  EXPECT_HAS(error_of([&] { synth::resolve_sweep_parameter("k", aliased, "c.yaml"); }), "'parameters.k.nominal' is not a plain number");
  const std::string twice = two_mass_with_k("parameters:\n  k: {nominal: 1.2, range: [0.9, &top 1.2]}\n", "k");
  EXPECT_HAS(error_of([&] { synth::resolve_sweep_parameter("k", twice, "c.yaml"); }), "'parameters.k.range' is not a plain number");
  std::string anchored_period = two_mass_with_k("", "1");
  anchored_period.replace(anchored_period.find("sample_time: 0.05"), 17, "sample_time: &T 0.05");
  EXPECT_HAS(error_of([&] { synth::with_value(anchored_period, "c.yaml", "system.sample_time", 0.1); }),
             "'system.sample_time' is not a plain number");
  // A value that is not a number is named before any config is read.
  const synth::SweepParameter k = synth::resolve_sweep_parameter("k", named, "c.yaml");
  EXPECT_HAS(error_of([&] { synth::config_at(k, std::nan(""), named, "c.yaml"); }), "k = ");
}

}  // namespace
