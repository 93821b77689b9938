// End-to-end: hinf-sim on the gps_ins_relative scenarios (seed 003, docs/experiments.md),
// checked from its output files only:
//  - both configs/scenarios/gps-ins-*.yaml run (shortened) and write their files; summary.json
//    agrees with trajectory.csv (the window maxima recomputed here) and with runs.csv;
//  - the same seed gives the same files, with one job or two;
//  - invalid input: exit 2 naming the key, nothing written;
//  - (heavy) the acceptance over 20 runs of 10 000 s: the EKF's NEES in the 99 % χ²
//    band and its accuracy; the REKF at p = 0.3 without γ violation or divergence, and ahead of
//    the EKF that ignores the products of inertia.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim_cli_test.hpp"

namespace fs = std::filesystem;
using namespace sim_cli_test;

namespace {
fs::path fresh_dir(const std::string& name) { return sim_cli_test::fresh_dir("gps_ins", name); }
const char* const kErrorBlocks[5][2] = {{"position_max_m", "pos"},
                                        {"velocity_max_mps", "vel"},
                                        {"attitude_max_deg", ""},
                                        {"rate_max_dps", "rate"},
                                        {"bias_max_dps", "bias"}};
}  // namespace

// 600 s (window 300–600 s): the files, and each filter's window maxima from trajectory.csv.
TEST(GpsInsScenarios, RunsBrieflyAndSummaryMatchesTrajectory) {
  for (const char* name : {"gps-ins-flyaround", "gps-ins-flyaround-as-printed"}) {
    const fs::path out = fresh_dir(name);
    ASSERT_EQ(run_scenario(name, "--duration 600", out), 0) << name;
    for (const char* f : {"trajectory.csv", "runs.csv", "summary.json"}) EXPECT_TRUE(fs::exists(out / f)) << f;
    const Columns tr = read_csv(out / "trajectory.csv");
    ASSERT_EQ(tr.rows.size(), 600u) << name;
    EXPECT_EQ(tr.header.size(), 1 + 15 + 2 * (15 * 3 + 1)) << name;
    const YAML::Node summary = YAML::LoadFile((out / "summary.json").string());
    EXPECT_EQ(summary["scenario_family"].as<std::string>(), "gps_ins_relative");
    for (const char* filter : {"ekf", "rekf"}) {
      const YAML::Node m = summary["filters"][filter];
      ASSERT_TRUE(m.IsMap()) << filter;
      const std::vector<std::vector<std::string>> blocks = {{"pos_x", "pos_y", "pos_z"},
                                                             {"vel_x", "vel_y", "vel_z"},
                                                             {"roll", "pitch", "yaw"},
                                                             {"rate_1", "rate_2", "rate_3"},
                                                             {"bias_1", "bias_2", "bias_3"}};
      for (int b = 0; b < 5; ++b) {
        double worst = 0;
        for (const auto& row : tr.rows)
          if (row[0] >= 300 && row[0] <= 600)
            for (const auto& c : blocks[b]) worst = std::max(worst, std::abs(row[tr.col(std::string(filter) + "_err_" + c)]));
        EXPECT_NEAR(m[kErrorBlocks[b][0]].as<double>(), worst, 1e-12 * worst) << name << " " << filter << " " << b;
      }
      // the NEES column's window mean
      double nees = 0;
      int n = 0;
      for (const auto& row : tr.rows)
        if (row[0] >= 300 && row[0] <= 600) nees += row[tr.col(std::string(filter) + "_nees")], ++n;
      EXPECT_NEAR(m["nees_mean"].as<double>(), nees / n, 1e-9 * nees / n) << name << " " << filter;
      // 3σ columns are positive
      EXPECT_GT(tr.rows.back()[tr.col(std::string(filter) + "_3sigma_roll")], 0.0);
    }
    fs::remove_all(out);
  }
}

TEST(GpsInsScenarios, SameSeedSameFilesWithOneJobOrTwo) {
  const fs::path a = fresh_dir("det_a"), b = fresh_dir("det_b");
  ASSERT_EQ(run_scenario("gps-ins-flyaround", "--duration 200 --runs 3 --seed 7", a), 0);
  ASSERT_EQ(run_scenario("gps-ins-flyaround", "--duration 200 --runs 3 --seed 7 --jobs 2", b), 0);
  for (const char* f : {"trajectory.csv", "runs.csv"}) EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
  const Columns runs = read_csv(a / "runs.csv");
  EXPECT_EQ(runs.rows.size(), 6u);  // 3 runs × 2 filters
  fs::remove_all(a);
  fs::remove_all(b);
}

// Invalid scenarios: exit 2, the message names the key, no output directory.
TEST(GpsInsInvalid, Exit2NamesKeyWritesNothing) {
  const struct {
    const char* from;
    const char* to;
    const char* message;
  } cases[] = {
      {"  accel_perturbation_sigma: 1.0e-6", "  accel_perturbation_sigmaa: 1.0e-6", "relative.accel_perturbation_sigmaa"},
      {"  inertia_products_fraction: 0.0", "  inertia_products_fraction: 0.6", "not positive definite"},
      {"  ekf:  {jacobian: full", "  ekf:  {gamma: 2, jacobian: full", "filters.ekf.gamma: only with type: rekf"},
      {"  ekf:  {jacobian: full", "  other:  {jacobian: full", "filters.other: needs type: ekf or rekf"},
      {"  phase_sigma_unit: cycles", "  phase_sigma_unit: radians", "gps.phase_sigma_unit"},
      {"duration: 10000", "duration: 10000.5", "duration = 10000.5: must be a whole multiple of sample_time"},
      {"metrics: {steady_state_window: [4000, 10000]", "metrics: {steady_state_window: [4000, 20000]",
       "metrics.steady_state_window"},
  };
  const std::string text = slurp(fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / "gps-ins-flyaround.yaml");
  for (const auto& c : cases) {
    std::string bad = text;
    const auto at = bad.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    bad.replace(at, std::string(c.from).size(), c.to);
    const fs::path cfg = fs::temp_directory_path() / ("gps_ins_bad_" + std::to_string(::getpid()) + ".yaml");
    std::ofstream(cfg) << bad;
    const fs::path out = fresh_dir("bad");
    const fs::path log = out.string() + ".log";
    EXPECT_EQ(run_scenario_file(cfg, "", out, log), 2) << c.to;
    EXPECT_NE(slurp(log).find(c.message), std::string::npos) << c.to << ": " << slurp(log);
    EXPECT_FALSE(fs::exists(out)) << c.to;
    fs::remove(log);
    fs::remove(cfg);
  }
}

// The acceptance (heavy: 3 × 20 runs of 10 000 s, ~45 s in Release).
TEST(GpsInsAcceptance, TwentyRunsAtZeroAndThirtyPercent) {
  const fs::path p0 = fresh_dir("p0");
  ASSERT_EQ(run_scenario("gps-ins-flyaround", "--runs 20 --jobs 2", p0), 0);
  const YAML::Node ekf = YAML::LoadFile((p0 / "summary.json").string())["filters"]["ekf"];
  // C5: mean NEES over 20 runs × the window in the 99 % χ² band of 15 degrees of freedom
  EXPECT_GE(ekf["nees_mean"]["mean"].as<double>(), 12.0);
  EXPECT_LE(ekf["nees_mean"]["mean"].as<double>(), 18.3);
  // C6: median over runs of the window maximum (EKF)
  EXPECT_LE(metric_median(ekf["position_max_m"]), 0.15);
  EXPECT_LE(metric_median(ekf["velocity_max_mps"]), 3e-4);
  EXPECT_LE(metric_median(ekf["attitude_max_deg"]), 3e-3);
  EXPECT_LE(metric_median(ekf["rate_max_dps"]), 2e-5);
  fs::remove_all(p0);

  // C7 and K4 at p = 0.3: the scenario with inertia_products_fraction 0.3
  std::string text = slurp(fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / "gps-ins-flyaround.yaml");
  const std::string from = "inertia_products_fraction: 0.0";
  text.replace(text.find(from), from.size(), "inertia_products_fraction: 0.3");
  const fs::path cfg = fs::temp_directory_path() / ("gps_ins_p03_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(cfg) << text;
  const fs::path p3 = fresh_dir("p3"), log = p3.string() + ".log";
  ASSERT_EQ(run_scenario_file(cfg, "--runs 20 --jobs 2 --quiet", p3, log), 0) << slurp(log);
  fs::remove(log);
  const Columns runs = read_csv(p3 / "runs.csv");
  int rekf_ahead = 0, rekf_rows = 0;
  for (std::size_t r = 0; r + 1 < runs.rows.size(); r += 2) {  // rows: ekf, rekf of each run
    const auto& e = runs.rows[r];
    const auto& k = runs.rows[r + 1];
    EXPECT_EQ(k[runs.col("gamma_violations")], 0.0);
    EXPECT_EQ(k[runs.col("diverged")], 0.0);
    rekf_ahead += k[runs.col("attitude_max_deg")] <= e[runs.col("attitude_max_deg")];
    ++rekf_rows;
  }
  EXPECT_EQ(rekf_rows, 20);
  EXPECT_GE(rekf_ahead, 14);  // K4: in at least 70 % of the runs
  fs::remove_all(p3);
  fs::remove(cfg);
}
