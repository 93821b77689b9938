// End-to-end: hinf-sim on the tumbling_hold scenarios (seed 004, docs/experiments.md),
// checked from its output files only:
//  - every configs/scenarios/tumbling-hold-*.yaml runs (shortened), writes its files, and its
//    summary.json agrees with its own trajectory.csv (RMS, maximum, Δv recomputed here);
//  - the acceptance figures, 10 Monte-Carlo runs: PWM steady RMS ≤ 1 cm per axis,
//    maximum ≤ 3 cm, velocity RMS ≤ 2 mm/s, settled by 200 s, Δv ≤ 1.1 × the ideal
//    actuator's, no pulse shorter than 40 ms; a true spin of 1.9 and 2.1 °/s (controller
//    designed at 2 °/s) steady maximum ≤ 5 cm, and the tumbling target with the feed-forward
//    of its current rate;
//  - invalid input: exit 2 naming the key, nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "sim_cli_test.hpp"

namespace fs = std::filesystem;
using namespace sim_cli_test;

namespace {

fs::path fresh_dir(const std::string& name) { return sim_cli_test::fresh_dir("hold", name); }

std::vector<std::string> hold_scenarios() {
  std::vector<std::string> v;
  for (const auto& e : fs::directory_iterator(fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios"))
    if (e.path().filename().string().rfind("tumbling-hold", 0) == 0) v.push_back(e.path().stem().string());
  std::sort(v.begin(), v.end());
  return v;
}

class HoldScenarios : public ::testing::TestWithParam<std::string> {};

// 300 s of each scenario (the steady window then starts at 150 s): the files, and the
// summary's metrics recomputed from trajectory.csv.
TEST_P(HoldScenarios, RunsBrieflyAndSummaryMatchesTrajectory) {
  const fs::path out = fresh_dir(GetParam());
  ASSERT_EQ(run_scenario(GetParam(), "--duration 300", out), 0);
  for (const char* f : {"trajectory.csv", "summary.json", "runs.csv", "controller.yaml", "position.png",
                        "velocity.png", "thrusters.png", "error_norms.png"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const YAML::Node summary = YAML::LoadFile((out / "summary.json").string());
  const YAML::Node m = summary["metrics"];
  EXPECT_EQ(summary["family"].as<std::string>(), "tumbling_hold");
  EXPECT_EQ(YAML::LoadFile((out / "controller.yaml").string())["format"].as<std::string>(), "hinf-controller/1");
  const Columns csv = read_csv(out / "trajectory.csv");
  ASSERT_EQ(csv.rows.size(), 3001u);
  const double start = summary["steady_state_start_s"].as<double>();
  EXPECT_DOUBLE_EQ(start, 150.0);
  double sum2[3] = {0, 0, 0}, vsum2[3] = {0, 0, 0}, max_err = 0, dv = 0;
  long count = 0;
  for (const auto& row : csv.rows) {
    for (int i = 0; i < 3; ++i) {
      const double pulse = row[csv.col("pulse_x") + static_cast<std::size_t>(i)];
      EXPECT_TRUE(pulse == -1 || pulse == 0 || pulse == 1);
      EXPECT_LE(std::abs(row[csv.col("force_x") + static_cast<std::size_t>(i)]), 5.0 + 1e-12);
      dv += std::abs(row[csv.col("force_x") + static_cast<std::size_t>(i)]) * 0.1 / 500.0;
    }
    if (row[0] < start) continue;
    ++count;
    for (int i = 0; i < 3; ++i) {
      const double e = row[csv.col("err_x") + static_cast<std::size_t>(i)];
      const double v = row[csv.col("vel_x") + static_cast<std::size_t>(i)];
      sum2[i] += e * e;
      vsum2[i] += v * v;
      max_err = std::max(max_err, std::abs(e));
    }
  }
  const double rms = std::sqrt(*std::max_element(sum2, sum2 + 3) / static_cast<double>(count));
  const double vrms = std::sqrt(*std::max_element(vsum2, vsum2 + 3) / static_cast<double>(count));
  EXPECT_NEAR(m["position_rms_m"].as<double>(), rms, 1e-12 * std::max(1.0, rms));
  EXPECT_NEAR(m["velocity_rms_mps"].as<double>(), vrms, 1e-12);
  EXPECT_NEAR(m["position_max_m"].as<double>(), max_err, 1e-15);
  // Δv from the interval means: equal unless a thruster reverses inside a 0.1 s interval
  EXPECT_LE(m["delta_v_mps"].as<double>(), dv * (1 + 1e-9) + 1e-9);
  EXPECT_GE(m["delta_v_mps"].as<double>(), dv * (1 - 1e-3));
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(All, HoldScenarios, ::testing::ValuesIn(hold_scenarios()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// The acceptance for the pulsed hold (10 runs) against the ideal actuator's Δv.
TEST(HoldAcceptance, PwmTenRuns) {
  const fs::path ideal = fresh_dir("ideal10"), pwm = fresh_dir("pwm10");
  ASSERT_EQ(run_scenario("tumbling-hold-ideal", "--runs 10 --no-plots", ideal), 0);
  ASSERT_EQ(run_scenario("tumbling-hold-pwm", "--runs 10 --no-plots", pwm), 0);
  const YAML::Node mi = YAML::LoadFile((ideal / "summary.json").string())["metrics"];
  const YAML::Node m = YAML::LoadFile((pwm / "summary.json").string())["metrics"];
  EXPECT_EQ(m["position_rms_m"]["count"].as<int>(), 10);
  EXPECT_LE(metric_max(m["position_rms_m"]), 0.01);
  EXPECT_LE(metric_max(m["position_max_m"]), 0.03);
  EXPECT_LE(metric_max(m["velocity_rms_mps"]), 0.002);
  ASSERT_EQ(m["settle_time_s"]["count"].as<int>(), 10);
  EXPECT_LE(metric_max(m["settle_time_s"]), 200.0);
  EXPECT_GE(m["min_pulse_s"]["min"].as<double>(), 0.04 - 1e-12);
  EXPECT_LE(metric_max(m["delta_v_mps"]), 1.1 * metric_mean(mi["delta_v_mps"]));
  // and the ideal actuator itself (no pulses): settled by 150 s, steady RMS ≤ 5 mm
  EXPECT_LE(metric_max(mi["settle_time_s"]), 150.0);
  EXPECT_LE(metric_max(mi["position_rms_m"]), 0.005);
  EXPECT_TRUE(mi["min_pulse_s"].IsNull());
  fs::remove_all(ideal);
  fs::remove_all(pwm);
}

// A true spin 5 % off the design's: bounded, steady maximum ≤ 5 cm (integral action).
TEST(HoldAcceptance, SpinOffNominalStaysWithinFiveCentimetres) {
  for (const char* name : {"tumbling-hold-spin-1.9", "tumbling-hold-spin-2.1"}) {
    const fs::path out = fresh_dir(name);
    ASSERT_EQ(run_scenario(name, "--runs 10 --no-plots", out), 0) << name;
    const YAML::Node m = YAML::LoadFile((out / "summary.json").string())["metrics"];
    EXPECT_LE(metric_max(m["position_max_m"]), 0.05) << name;
    EXPECT_EQ(m["position_max_m"]["count"].as<int>(), 10) << name;
    fs::remove_all(out);
  }
}

// The tumbling target (0.42 °/s off the design's spin) with the feed-forward of its current
// rate: steady maximum ≤ 5 cm over 10 runs.
TEST(HoldAcceptance, TumblingTargetWithScheduledFeedforward) {
  const fs::path out = fresh_dir("tumbling");
  ASSERT_EQ(run_scenario("tumbling-hold-tumbling", "--runs 10 --no-plots", out), 0);
  const YAML::Node m = YAML::LoadFile((out / "summary.json").string())["metrics"];
  EXPECT_LE(metric_max(m["position_max_m"]), 0.05);
  EXPECT_EQ(m["position_max_m"]["count"].as<int>(), 10);
  fs::remove_all(out);
}

// Invalid scenarios: exit 2, the message names the key, no output directory.
TEST(HoldInvalid, Exit2NamesKeyWritesNothing) {
  const struct {
    const char* from;
    const char* to;
    const char* message;
  } cases[] = {{"modulator: {type: pwm, period: 1.0, carry_remainder: true}", "modulator: {type: pwn}",
                "modulator.type = 'pwn'"},
               {"modulator: {type: pwm, period: 1.0, carry_remainder: true}", "modulator: {type: pwm, period: 0.25}",
                "modulator.period = 0.25: must be a whole multiple of control_sample_time 0.1"},
               {"modulator: {type: pwm, period: 1.0, carry_remainder: true}", "modulator: {type: ideal, tau: 1}",
                "modulator.tau: only with modulator.type: pwpf"},
               {"control_sample_time: 0.1 ", "control_sample_time: 0.1005 ",
                "control_sample_time = 0.1005: must be a whole multiple of integration_step"},
               {"inertia: [1200, 1000, 800]", "inertia: [3000, 1000, 800]", "target.inertia: violates the triangle"},
               {"controller: {synthesize: ../tumbling-hold.yaml}", "controller: {file: missing.yaml}",
                "controller.file: file '.*missing.yaml' does not exist"},
               {"feedforward: {rate_deg_s: [0, 0, 2]}", "feedforward: {from: target_rate, rate_deg_s: [0, 0, 2]}",
                "feedforward.rate_deg_s: not with from: target_rate"},
               // the scenario's key, never the runtime's class (was "hinf::runtime::PwmModulator: ...")
               {"min_on_time: 0.04", "min_on_time: 1e200", "thrusters.min_on_time = 1e200: must be at most the PWM period 1 s"},
               // was exit 4, "internal error: summary.json: refusing to write a non-finite number"
               {"feedforward: {rate_deg_s: [0, 0, 2]}", "feedforward: {rate_deg_s: [1e200, 0, 2]}",
                "feedforward: the equilibrium force U\\* .* is not finite"}};
  const std::string text = slurp(fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / "tumbling-hold-pwm.yaml");
  int i = 0;
  for (const auto& c : cases) {
    std::string bad = text;
    const std::size_t at = bad.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    bad.replace(at, std::string(c.from).size(), c.to);
    const fs::path dir = fresh_dir("invalid" + std::to_string(i++));
    fs::create_directories(dir);
    const fs::path scenario = dir / "bad.yaml", out = dir / "out", log = dir / "log";
    std::ofstream(scenario) << bad;
    fs::copy_file(fs::path(HINF_SOURCE_DIR) / "configs" / "tumbling-hold.yaml", fs::path(dir.parent_path()) / "tumbling-hold.yaml",
                  fs::copy_options::overwrite_existing);
    EXPECT_EQ(run_scenario_file(scenario, "", out, log), 2) << c.to << "\n" << slurp(log);
    EXPECT_TRUE(std::regex_search(slurp(log), std::regex(c.message))) << c.message << "\n" << slurp(log);
    EXPECT_FALSE(fs::exists(out)) << c.to;
    fs::remove_all(dir);
  }
}

// No output replaces a file the run reads (issue 34): with --out the scenario's own
// directory, the synthesis config named controller.yaml would be replaced by the run's
// controller.yaml. Exit 2 naming it, the config unchanged, nothing written.
TEST(HoldInvalid, OutputsNeverReplaceTheFilesTheRunReads) {
  const fs::path dir = fresh_dir("inputs");
  fs::create_directories(dir);
  std::string text = slurp(fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / "tumbling-hold-ideal.yaml");
  const std::string from = "controller: {synthesize: ../tumbling-hold.yaml}";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "controller: {synthesize: controller.yaml}");
  std::ofstream(dir / "scenario.yaml") << text;
  fs::copy_file(fs::path(HINF_SOURCE_DIR) / "configs" / "tumbling-hold.yaml", dir / "controller.yaml");
  const std::string config = slurp(dir / "controller.yaml");
  const fs::path log = dir.string() + ".log";
  EXPECT_EQ(run_scenario_file(dir / "scenario.yaml", "--duration 10 --no-plots", dir, log), 2) << slurp(log);
  EXPECT_NE(slurp(log).find("is the input file '" + (dir / "controller.yaml").string() + "'"), std::string::npos)
      << slurp(log);
  EXPECT_EQ(slurp(dir / "controller.yaml"), config);
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"controller.yaml", "scenario.yaml"}));
  fs::remove_all(dir);
  fs::remove(log);
}

// A --duration shorter than one control period would run no sample: refused (issue 34).
TEST(HoldInvalid, DurationOfNoSampleIsRefused) {
  const fs::path dir = fresh_dir("no_sample");
  const fs::path log = dir.string() + ".log";
  const fs::path scenario = fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / "tumbling-hold-ideal.yaml";
  EXPECT_EQ(run_scenario_file(scenario, "--duration 1e-9", dir, log), 2) << slurp(log);
  EXPECT_NE(slurp(log).find("--duration 1e-9: is shorter than one sample time (0.1 s)"), std::string::npos)
      << slurp(log);
  EXPECT_FALSE(fs::exists(dir));
  fs::remove(log);
}

// 9e5 s is 9e6 control samples (under the 1e7 every family allows) but 9e8 integration steps
// of 1 ms: the hold family's own cap (1e8, the scenario file's rule) holds for --duration too.
TEST(HoldInvalid, DurationOfTooManyIntegrationStepsIsRefused) {
  const fs::path dir = fresh_dir("too_many_ticks");
  const fs::path log = dir.string() + ".log";
  const fs::path scenario = fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / "tumbling-hold-ideal.yaml";
  EXPECT_EQ(run_scenario_file(scenario, "--duration 900000", dir, log), 2) << slurp(log);
  EXPECT_NE(slurp(log).find("--duration 900000: needs more than"), std::string::npos) << slurp(log);
  EXPECT_NE(slurp(log).find("integration steps of 0.001 s"), std::string::npos) << slurp(log);
  EXPECT_FALSE(fs::exists(dir));
  fs::remove(log);
}

}  // namespace
