// The linear_plant family (sim/families/linear_plant, docs/maths.md §33): the predicted RMS
// (229) against closed forms, the runs against the predicted RMS, the Kalman predictor against
// the H∞ filter where theory orders them, and the scenario reader's refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hinf/common/error.hpp"
#include "hinf/sim/linear_plant_scenario_yaml.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/synthesis.hpp"
#include "scratch_dir.hpp"

namespace {

using Eigen::MatrixXd;
namespace fs = std::filesystem;

MatrixXd m1(double v) { return MatrixXd::Constant(1, 1, v); }
const Eigen::VectorXd kNoDelta;  // a plant without uncertainty: no block of F

// x(k+1) = a x + b w, y = x + d v, z = x: scalar, no uncertainty, no known input.
hinf::sim::LinearPlantScenario scalar_plant(double a, double b, double d) {
  hinf::sim::LinearPlantScenario s;
  s.plant.A = m1(a);
  s.plant.B = m1(b);
  s.plant.C = m1(1);
  s.plant.D = m1(d);
  s.plant.L = m1(1);
  s.plant.H = MatrixXd(1, 0);
  s.plant.E = MatrixXd(0, 1);
  s.plant.G = MatrixXd(1, 0);
  return s;
}

// A first-order filter that ignores y: ẑ = 0, so e = z = x.
hinf::sim::LtiGains zero_estimate() { return {m1(0), m1(0), m1(0), MatrixXd()}; }

TEST(LinearPlantPrediction, EstimateZeroGivesThePlantsStationaryStd) {
  auto s = scalar_plant(0.9, 2.0, 0.5);
  s.process_std = 0.3;
  // Var x = b² σ_w² / (1 − a²)
  EXPECT_NEAR(hinf::sim::predicted_error_rms(s, zero_estimate(), kNoDelta), std::sqrt(4 * 0.09 / (1 - 0.81)), 1e-12);
}

TEST(LinearPlantPrediction, FeedthroughOfYLeavesTheMeasurementNoise) {
  auto s = scalar_plant(0.5, 1.0, 0.25);
  s.measurement_std = 2;
  hinf::sim::LtiGains g = zero_estimate();
  g.D_F = m1(1);  // ẑ = y = x + d v: e = −d v
  EXPECT_NEAR(hinf::sim::predicted_error_rms(s, g, kNoDelta), 0.25 * 2, 1e-12);
}

TEST(LinearPlantPrediction, UnstableTruthHasNoStationaryValue) {
  EXPECT_TRUE(std::isnan(hinf::sim::predicted_error_rms(scalar_plant(1.01, 1, 1), zero_estimate(), kNoDelta)));
}

// 100 000 samples of the Kalman predictor of a damped oscillator: the measured RMS within 3 %
// of (229). The RMS of ~1e5 samples correlated over ~10 samples has a relative standard error
// below 1 %; 3 % is about four of them.
TEST(LinearPlantRuns, MeasuredRmsMatchesThePrediction) {
  hinf::sim::LinearPlantScenario s;
  s.plant.A = (MatrixXd(2, 2) << 0.99, 0.05, -0.2, 0.95).finished();
  s.plant.B = (MatrixXd(2, 1) << 0, 0.3).finished();
  s.plant.C = (MatrixXd(1, 2) << 1, 0).finished();
  s.plant.D = m1(0.5);
  s.plant.L = MatrixXd::Identity(2, 2);
  s.plant.H = MatrixXd(2, 0);
  s.plant.E = MatrixXd(0, 2);
  s.plant.G = MatrixXd(2, 0);
  s.duration = 100000;
  const auto kalman = hinf::synth::kalman_predictor(s.plant, hinf::synth::Settings());
  hinf::sim::LinearPlantFilter f;
  f.name = "kalman";
  f.gains = {kalman.filter.A_F, kalman.filter.B_F, kalman.filter.C_F, kalman.filter.D_F};
  hinf::sim::LinearPlantRunOptions o;
  o.window_start = 1000;
  const auto stats = hinf::sim::run_linear_plant(s, {f}, o, 42);
  const double predicted = hinf::sim::predicted_error_rms(s, f.gains, kNoDelta);
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_EQ(stats[0].predicted_rms, predicted);
  EXPECT_FALSE(stats[0].diverged);
  EXPECT_NEAR(stats[0].error_rms / predicted, 1.0, 0.03) << stats[0].error_rms << " vs " << predicted;
  EXPECT_GT(stats[0].error_max, stats[0].error_rms);
}

// F = diag(δ₁, δ₂) on a structured plant: A + H diag(δ) E, block by block.
TEST(LinearPlantTruth, EachBlockOfFHasItsDelta) {
  auto s = scalar_plant(0.5, 1, 1);
  s.plant.A = MatrixXd::Identity(2, 2) * 0.5;
  s.plant.H = MatrixXd::Identity(2, 2);
  s.plant.E = (MatrixXd(2, 2) << 1, 0, 0, 2).finished();
  s.plant.F_blocks = {1, 1};
  ASSERT_EQ(s.uncertainty_blocks(), 2);
  const MatrixXd A = s.truth_A((Eigen::VectorXd(2) << 0.5, -0.25).finished());
  EXPECT_EQ(A, (MatrixXd(2, 2) << 1.0, 0, 0, 0).finished());
}

std::string write_scenario(const hinf::test::ScratchDir& dir, const std::string& body) {
  const std::string path = (dir.path / "s.yaml").string();
  std::ofstream(path) << "scenario: linear_plant\nconfig: " << HINF_SOURCE_DIR << "/configs/example-parameters.yaml\n"
                      << body;
  return path;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// On the nominal plant under the noise the Kalman predictor is designed for, no one-step
// predictor has a smaller mean-square error (docs/maths.md §33): its predicted RMS is at most
// the H∞ filter's. The reader synthesises the H∞ filter and computes the predictor itself.
TEST(LinearPlantScenario, KalmanPredictorIsBestOnTheNominalPlant) {
  const hinf::test::ScratchDir dir("linear_plant_nominal");
  const std::string path = write_scenario(dir, "duration: 10\nfilters: {hinf: {}, kalman: {}}\n");
  const auto e = hinf::sim::parse_linear_plant_scenario(read_text(path), path);
  ASSERT_EQ(e.filters.size(), 2u);
  EXPECT_EQ(e.filters[0].type, "hinf");
  EXPECT_EQ(e.filters[1].type, "kalman");
  EXPECT_DOUBLE_EQ(e.scenario.sample_time, 0.05);  // the config's
  const Eigen::VectorXd nominal = Eigen::VectorXd::Zero(e.scenario.uncertainty_blocks());
  ASSERT_EQ(nominal.size(), 1);  // one named parameter: one block
  const double hinf = hinf::sim::predicted_error_rms(e.scenario, e.filters[0].gains, nominal);
  const double kalman = hinf::sim::predicted_error_rms(e.scenario, e.filters[1].gains, nominal);
  EXPECT_TRUE(std::isfinite(hinf));
  EXPECT_LE(kalman, hinf);
  EXPECT_EQ(e.inputs.size(), 1u);  // the config
  EXPECT_NE(e.filters[0].gains_yaml.find("gamma"), std::string::npos);
}

// uncertainty_delta: random draws each run's δ on [−1, 1], the same for every filter of the run,
// another in the next run; the seed fixes them.
TEST(LinearPlantScenario, RandomUncertaintyDrawsOneDeltaPerRun) {
  const hinf::test::ScratchDir dir("linear_plant_random");
  const std::string path =
      write_scenario(dir, "duration: 1\nfilters: {kalman: {}}\ntruth: {uncertainty_delta: random}\n");
  const auto e = hinf::sim::parse_linear_plant_scenario(read_text(path), path);
  EXPECT_TRUE(e.scenario.random_uncertainty);
  std::vector<double> deltas;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto stats = hinf::sim::run_linear_plant(e.scenario, e.filters, e.options, seed);
    ASSERT_EQ(stats[0].delta.size(), 1);
    EXPECT_LE(std::abs(stats[0].delta(0)), 1.0);
    EXPECT_EQ(stats[0].delta(0), hinf::sim::run_linear_plant(e.scenario, e.filters, e.options, seed)[0].delta(0));
    deltas.push_back(stats[0].delta(0));
  }
  std::sort(deltas.begin(), deltas.end());
  EXPECT_LT(deltas.front(), -0.3);  // spread over the range (20 uniform draws)
  EXPECT_GT(deltas.back(), 0.3);
  EXPECT_TRUE(std::adjacent_find(deltas.begin(), deltas.end()) == deltas.end());
}

TEST(LinearPlantScenario, RefusesWhatItCannotRun) {
  const hinf::test::ScratchDir dir("linear_plant_refused");
  const auto refused = [&](const std::string& body, const std::string& expected) {
    const std::string path = write_scenario(dir, body);
    try {
      hinf::sim::parse_linear_plant_scenario(read_text(path), path);
      ADD_FAILURE() << "accepted: " << body;
    } catch (const hinf::Error& err) {
      EXPECT_EQ(err.code(), hinf::ErrorCode::InvalidInput) << err.what();
      EXPECT_NE(std::string(err.what()).find(expected), std::string::npos) << err.what();
    }
  };
  refused("duration: 10\nfilters: {hinf: {}}\nnoise: {process_sd: 1}\n", "process_sd");
  refused("duration: 10.01\nfilters: {hinf: {}}\n", "whole multiple of sample_time 0.05");
  refused("duration: 10\nfilters: {mine: {}}\n", "needs type: hinf or kalman");
  refused("duration: 10\nfilters: {kalman: {gains: s.yaml}}\n", "only with type: hinf");
  refused("duration: 10\nfilters: {hinf: {}}\ntruth: {uncertainty_delta: 1.5}\n", "must be in [-1, 1]");
  refused("duration: 10\nfilters: {hinf: {}}\ntruth: {uncertainty_delta: randm}\n", "uncertainty_delta");
  const std::string gains = std::string(HINF_SOURCE_DIR) + "/tests/golden/paper-dbar0.05.yaml";
  refused("duration: 10\nfilters: {hinf: {gains: " + gains + "}}\n", "the config's plant has m = 1, l = 2");
  refused("duration: 10\nfilters: {hinf: {}}\ntruth: {parameters: {kk: 1}}\n", "did you mean 'k'");
  refused("duration: 10\nfilters: {hinf: {}}\ntruth: {parameters: {k: 1.1}}\n", "range [0.95, 1.05]");
  refused("duration: 10\nfilters: {hinf: {}}\ntruth: {parameters: {k: 1}, uncertainty_delta: 0}\n", "not both");
}

// truth.parameters names the plant in the parameters' units: k = 1.05, the top of the example's
// range [0.95, 1.05] about ν = 1, is δ = 1, the run of uncertainty_delta: 1 to the last bit; k
// drawn at random stays in its range and runs.csv names it.
TEST(LinearPlantScenario, TheTruthIsGivenByTheParametersValues) {
  const hinf::test::ScratchDir dir("linear_plant_parameters");
  const auto parsed = [&](const std::string& truth) {
    const std::string path = write_scenario(dir, "duration: 5\nfilters: {kalman: {}}\ntruth: " + truth + "\n");
    return hinf::sim::parse_linear_plant_scenario(read_text(path), path);
  };
  const auto by_value = parsed("{parameters: {k: 1.05}}"), by_delta = parsed("{uncertainty_delta: 1}");
  ASSERT_EQ(by_value.scenario.truth_parameters.size(), 1u);
  const auto a = hinf::sim::run_linear_plant(by_value.scenario, by_value.filters, by_value.options, 3);
  const auto b = hinf::sim::run_linear_plant(by_delta.scenario, by_delta.filters, by_delta.options, 3);
  EXPECT_EQ(a[0].delta, b[0].delta);
  EXPECT_EQ(a[0].error_rms, b[0].error_rms);
  EXPECT_EQ(by_value.scenario.truth_A(a[0].delta), by_delta.scenario.truth_A(b[0].delta));
  const auto random = parsed("{parameters: {k: random}}");
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const double k = 1 + 0.05 * hinf::sim::run_linear_plant(random.scenario, random.filters, random.options, seed)[0].delta(0);
    EXPECT_TRUE(k >= 0.95 && k <= 1.05) << k;
  }
}

}  // namespace
