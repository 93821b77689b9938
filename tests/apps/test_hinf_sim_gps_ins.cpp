// End-to-end: hinf-sim on the gps_ins_relative scenarios (seed 003, docs/experiments.md),
// checked from its output files only:
//  - every configs/scenarios/gps-ins-*.yaml runs (shortened) and write their files; summary.json
//    agrees with trajectory.csv (the window maxima recomputed here) and with runs.csv;
//  - table1.csv: its row for the scenario's own p is summary.json's per-axis maxima, its row
//    for another p that of a separate run of the scenario with that p; --no-plots;
//  - the same seed gives the same files, with one job or two; phase_mode: double_difference;
//    explicit A, C, L of the REKF;
//  - invalid input: exit 2 naming the key, nothing written;
//  - (heavy) the acceptance over 20 runs of 10 000 s: the EKF's NEES in the 99 % χ²
//    band; the EKF's and the REKF's accuracy; both REKFs at p = 0.3 without γ violation or
//    divergence, and ahead of the EKF that ignores the products of inertia.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <tuple>
#include <string>
#include <vector>

#include "sim_cli_test.hpp"

namespace fs = std::filesystem;
using namespace sim_cli_test;

namespace {
fs::path fresh_dir(const std::string& name) { return sim_cli_test::fresh_dir("gps_ins", name); }
const char* const kFigures[5] = {"fig1_position.png", "fig2_velocity.png", "fig3_attitude.png", "fig4_rate.png",
                                 "error_norms.png"};
const char* const kErrorBlocks[5][2] = {{"position_max_m", "pos"},
                                        {"velocity_max_mps", "vel"},
                                        {"attitude_max_deg", ""},
                                        {"rate_max_dps", "rate"},
                                        {"bias_max_dps", "bias"}};
std::vector<std::string> filter_names(const YAML::Node& summary) {
  std::vector<std::string> names;
  for (const auto& f : summary["filters"]) names.push_back(f.first.as<std::string>());
  return names;
}

// The shipped scenario with `from` replaced by `to`, written to a temporary file.
fs::path edited_scenario(const std::string& tag, const std::vector<std::pair<std::string, std::string>>& edits) {
  return sim_cli_test::edited_scenario("gps-ins-flyaround", tag, edits);
}
const std::pair<std::string, std::string> kNoTable1 = {",\n          table1_products_fractions: [0, 0.1, 0.3]}", "}"};
}  // namespace

// 600 s (window 300–600 s): the files, and each filter's window maxima from trajectory.csv.
TEST(GpsInsScenarios, RunsBrieflyAndSummaryMatchesTrajectory) {
  std::vector<std::string> names;  // every configs/scenarios/gps-ins-*.yaml
  for (const auto& entry : fs::directory_iterator(fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios"))
    if (entry.path().extension() == ".yaml" && entry.path().filename().string().rfind("gps-ins-", 0) == 0)
      names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  ASSERT_GE(names.size(), 3u);
  for (const std::string& name : names) {
    const fs::path out = fresh_dir(name);
    ASSERT_EQ(run_scenario(name, "--duration 600", out), 0) << name;
    for (const char* f : {"trajectory.csv", "runs.csv", "summary.json", "table1.csv"}) EXPECT_TRUE(fs::exists(out / f)) << f;
    for (const char* png : kFigures) EXPECT_EQ(slurp(out / png).substr(0, 8), "\x89PNG\r\n\x1a\n") << png;
    const YAML::Node summary = YAML::LoadFile((out / "summary.json").string());
    EXPECT_EQ(summary["scenario_family"].as<std::string>(), "gps_ins_relative");
    const std::vector<std::string> filters = filter_names(summary);
    ASSERT_GE(filters.size(), 2u) << name;
    const Columns tr = read_csv(out / "trajectory.csv");
    ASSERT_EQ(tr.rows.size(), 600u) << name;
    EXPECT_EQ(tr.header.size(), 1 + 15 + filters.size() * (15 * 3 + 1)) << name;
    for (const std::string& filter : filters) {
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
  for (const char* f : {"trajectory.csv", "runs.csv", "table1.csv"}) EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
  const Columns runs = read_csv(a / "runs.csv");
  EXPECT_EQ(runs.rows.size(), 9u);  // 3 runs × 3 filters
  fs::remove_all(a);
  fs::remove_all(b);
}

// table1.csv, one 600 s run: the row of the scenario's own p (0) is its summary.json's per-axis
// window maxima; the row of p = 0.3 is what a separate run of the scenario with p = 0.3 writes
// in its trajectory.csv (the same seed). --no-plots writes no png.
TEST(GpsInsScenarios, Table1RowsAreTheCampaignsOfEachFraction) {
  const fs::path own = fresh_dir("t1_own"), other = fresh_dir("t1_p3");
  ASSERT_EQ(run_scenario("gps-ins-flyaround", "--duration 600 --no-plots", own), 0);
  for (const char* png : kFigures) EXPECT_FALSE(fs::exists(own / png)) << png;
  const fs::path cfg = edited_scenario("p3", {{"inertia_products_fraction: 0.0", "inertia_products_fraction: 0.3"}, kNoTable1});
  const fs::path log = other.string() + ".log";
  ASSERT_EQ(run_scenario_file(cfg, "--duration 600 --no-plots --quiet", other, log), 0) << slurp(log);
  EXPECT_FALSE(fs::exists(other / "table1.csv"));
  const Columns table = read_csv(own / "table1.csv");
  ASSERT_EQ(table.rows.size(), 9u);  // p = 0, 0.1, 0.3 × ekf, rekf, rekf_p30
  const char* const axes[3][3] = {{"roll", "pitch", "yaw"}, {"rate_1", "rate_2", "rate_3"}, {"bias_1", "bias_2", "bias_3"}};
  const char* const table_columns[3][3] = {{"attitude_roll_deg", "attitude_pitch_deg", "attitude_yaw_deg"},
                                           {"rate_1_dps", "rate_2_dps", "rate_3_dps"},
                                           {"bias_1_dps", "bias_2_dps", "bias_3_dps"}};
  const std::vector<std::string> filters = {"ekf", "rekf", "rekf_p30"};
  for (const auto& [dir, p, first_row] : {std::tuple{own, 0.0, 0}, std::tuple{other, 0.3, 6}}) {
    const Columns tr = read_csv(dir / "trajectory.csv");
    for (std::size_t f = 0; f < filters.size(); ++f) {
      const auto& row = table.rows[static_cast<std::size_t>(first_row) + f];
      EXPECT_EQ(row[table.col("inertia_products_fraction")], p);
      EXPECT_EQ(row[table.col("runs")], 1.0);
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
          double worst = 0;
          for (const auto& t : tr.rows)
            if (t[0] >= 300 && t[0] <= 600) worst = std::max(worst, std::abs(t[tr.col(filters[f] + "_err_" + axes[b][a])]));
          EXPECT_NEAR(row[table.col(table_columns[b][a])], worst, 1e-12 * worst) << p << " " << filters[f] << " " << axes[b][a];
        }
    }
  }
  fs::remove(log);
  fs::remove(cfg);
  fs::remove_all(own);
  fs::remove_all(other);
}

// phase_mode: double_difference runs every filter on the 16-row model (193a): finite
// statistics, and other estimates than the single differences' on the same seed.
TEST(GpsInsScenarios, DoubleDifferencesRun) {
  const fs::path sd = fresh_dir("sd"), dd = fresh_dir("dd");
  ASSERT_EQ(run_scenario("gps-ins-flyaround", "--duration 600 --no-plots", sd), 0);
  const fs::path cfg = edited_scenario("dd", {{"phase_mode: single_difference", "phase_mode: double_difference"}, kNoTable1});
  const fs::path log = dd.string() + ".log";
  ASSERT_EQ(run_scenario_file(cfg, "--duration 600 --no-plots --quiet", dd, log), 0) << slurp(log);
  const YAML::Node summary = YAML::LoadFile((dd / "summary.json").string());
  for (const std::string& f : filter_names(summary))
    for (const auto& [key, unused] : kErrorBlocks) {
      (void)unused;
      EXPECT_TRUE(std::isfinite(summary["filters"][f][key].as<double>())) << f << " " << key;
    }
  EXPECT_NE(slurp(sd / "trajectory.csv"), slurp(dd / "trajectory.csv"));
  fs::remove(log);
  fs::remove(cfg);
  fs::remove_all(sd);
  fs::remove_all(dd);
}

// Explicit A, C, L of a REKF (each instead of its (197) form): zero matrices make the REKF the
// EKF, every column of trajectory.csv equal (C1 through the scenario file); an L that puts
// L P Lᵀ above γ² makes the γ condition fail, counted in summary.json.
TEST(GpsInsScenarios, ExplicitRekfUncertainty) {
  const auto matrix = [](int rows, double diagonal) {
    std::string m = "[";
    for (int i = 0; i < rows; ++i) {
      m += i ? ", [" : "[";
      for (int j = 0; j < 15; ++j) m += (j ? ", " : "") + std::string(i == j && diagonal != 0 ? "1.0e6" : "0");
      m += "]";
    }
    return m + "]";
  };
  const std::string ekf_line = "  ekf:  {jacobian: full, inertia_uncertainty_fraction: 0.0}\n";
  const std::string zero = ekf_line + "  rekf: {A: " + matrix(15, 0) + ", L: " + matrix(15, 0) + ", C: " + matrix(19, 0) + "}\n";
  const std::string large_L = ekf_line + "  rekf: {L: " + matrix(15, 1) + "}\n";
  const std::string text = slurp(fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / "gps-ins-flyaround.yaml");
  const std::string filters = text.substr(text.find("filters:\n") + 9, text.find("metrics:") - text.find("filters:\n") - 9);
  for (const auto& [tag, block] : {std::pair{"zero", zero}, std::pair{"large_l", large_L}}) {
    const fs::path cfg = edited_scenario(tag, {{filters, block}, kNoTable1});
    const fs::path out = fresh_dir(tag), log = out.string() + ".log";
    ASSERT_EQ(run_scenario_file(cfg, "--duration 600 --no-plots --quiet", out, log), 0) << slurp(log);
    const YAML::Node rekf = YAML::LoadFile((out / "summary.json").string())["filters"]["rekf"];
    if (std::string(tag) == "zero") {
      const Columns tr = read_csv(out / "trajectory.csv");
      int compared = 0;
      for (std::size_t c = 0; c < tr.header.size(); ++c)
        if (tr.header[c].rfind("ekf_", 0) == 0) {
          const int r = tr.col("rekf_" + tr.header[c].substr(4));
          ASSERT_GE(r, 0) << tr.header[c];
          for (const auto& row : tr.rows) EXPECT_EQ(row[c], row[static_cast<std::size_t>(r)]) << tr.header[c];
          ++compared;
        }
      EXPECT_EQ(compared, 15 + 15 + 15 + 1);
      EXPECT_EQ(rekf["gamma_violations"].as<double>(), 0.0);
    } else {
      EXPECT_GT(rekf["gamma_violations"].as<double>(), 0.0);
    }
    fs::remove(log);
    fs::remove(cfg);
    fs::remove_all(out);
  }
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
      {"kappa_C: 1.0e-3,\n         inertia_uncertainty_fraction: 0.03}", "kappa_C: 1.0e-3, C: [[1, 2]],\n         inertia_uncertainty_fraction: 0.03}",
       "filters.rekf.kappa_C: give C or kappa_C, not both"},
      {"kappa_C: 1.0e-3,\n         inertia_uncertainty_fraction: 0.03}", "L: [[1, 2]],\n         inertia_uncertainty_fraction: 0.03}",
       "filters.rekf.L"},
      {"  ekf:  {jacobian: full", "  ekf:  {A: {diag: [1, 1]}, jacobian: full", "filters.ekf.A: only with type: rekf"},
      {"table1_products_fractions: [0, 0.1, 0.3]", "table1_products_fractions: [0, 0.1, 0.9]",
       "metrics.table1_products_fractions: 0.9 at index 2 makes the true inertia not positive definite"},
      {"table1_products_fractions: [0, 0.1, 0.3]", "table1_products_fractions: [0, 0.3, 0.1]",
       "metrics.table1_products_fractions: must be increasing fractions in [0, 1), got 0.1 at index 2"},
      // a variance that underflows or overflows: the scenario's key, never a filter's class
      // (was "Ekf: R is not positive definite (Cholesky failed)")
      {"noise_deg_h: 0.05", "noise_deg_h: 4.9e-324", "gyro.noise_deg_h = 5e-324: a standard deviation must lie in"},
      {"pseudorange_sigma: 1.0", "pseudorange_sigma: 1e200", "gps.pseudorange_sigma = 1e200"},
      {"initial_error_sigma: {position: 10", "initial_error_sigma: {position: 1e-200", "initial_error_sigma.position"},
      // a refusal at run time, by the filter's key (was "Rekf: Q has a non-finite entry")
      {"inertia_uncertainty_fraction: 0.03}", "inertia_uncertainty_fraction: 1e200}",
       "filters.rekf: Q has a non-finite entry (built from"},
  };
  for (const auto& c : cases) {
    const fs::path cfg = edited_scenario("bad", {{c.from, c.to}});
    const fs::path out = fresh_dir("bad");
    const fs::path log = out.string() + ".log";
    EXPECT_EQ(run_scenario_file(cfg, "", out, log), 2) << c.to;
    EXPECT_NE(slurp(log).find(c.message), std::string::npos) << c.to << ": " << slurp(log);
    EXPECT_FALSE(fs::exists(out)) << c.to;
    fs::remove(log);
    fs::remove(cfg);
  }
}

// The acceptance (heavy: 20 runs of 10 000 s at p = 0 with the table-1 campaigns at
// p = 0.1 and 0.3, 20 runs at p = 0.3, 20 runs with double differences; ~85 s in Release).
TEST(GpsInsAcceptance, TwentyRunsAtZeroAndThirtyPercent) {
  const fs::path p0 = fresh_dir("p0");
  ASSERT_EQ(run_scenario("gps-ins-flyaround", "--runs 20 --jobs 2 --no-plots", p0), 0);
  const YAML::Node filters = YAML::LoadFile((p0 / "summary.json").string())["filters"];
  const YAML::Node ekf = filters["ekf"];
  // C5: mean NEES over 20 runs × the window in the 99 % χ² band of 15 degrees of freedom
  EXPECT_GE(ekf["nees_mean"]["mean"].as<double>(), 12.0);
  EXPECT_LE(ekf["nees_mean"]["mean"].as<double>(), 18.3);
  // C6: median over runs of the window maximum, the EKF and the REKF
  for (const char* name : {"ekf", "rekf"}) {
    const YAML::Node m = filters[name];
    EXPECT_LE(metric_median(m["position_max_m"]), 0.15) << name;
    EXPECT_LE(metric_median(m["velocity_max_mps"]), 3e-4) << name;
    EXPECT_LE(metric_median(m["attitude_max_deg"]), 3e-3) << name;
    EXPECT_LE(metric_median(m["rate_max_dps"]), 2e-5) << name;
  }
  fs::remove_all(p0);

  // C7 and K4 at p = 0.3, for both REKFs (p_f = 0.03 and 0.3)
  const fs::path cfg = edited_scenario("p03", {{"inertia_products_fraction: 0.0", "inertia_products_fraction: 0.3"}, kNoTable1});
  const fs::path p3 = fresh_dir("p3"), log = p3.string() + ".log";
  ASSERT_EQ(run_scenario_file(cfg, "--runs 20 --jobs 2 --quiet --no-plots", p3, log), 0) << slurp(log);
  fs::remove(log);
  const Columns runs = read_csv(p3 / "runs.csv");
  ASSERT_EQ(runs.rows.size(), 60u);  // rows: ekf, rekf, rekf_p30 of each run
  for (std::size_t k : {1u, 2u}) {
    int ahead = 0;
    for (std::size_t r = 0; r < runs.rows.size(); r += 3) {
      const auto& e = runs.rows[r];
      const auto& rekf = runs.rows[r + k];
      EXPECT_EQ(rekf[runs.col("gamma_violations")], 0.0) << k;
      EXPECT_EQ(rekf[runs.col("diverged")], 0.0) << k;
      ahead += rekf[runs.col("attitude_max_deg")] <= e[runs.col("attitude_max_deg")];
    }
    EXPECT_GE(ahead, 14) << k;  // K4: in at least 70 % of the runs
  }
  fs::remove_all(p3);
  fs::remove(cfg);

  // phase_mode: double_difference, p = 0: the EKF with the correlated R of (193a) is
  // consistent (C5's band) and meets C6
  const fs::path dd_cfg = edited_scenario("dd20", {{"phase_mode: single_difference", "phase_mode: double_difference"}, kNoTable1});
  const fs::path dd = fresh_dir("dd20"), dd_log = dd.string() + ".log";
  ASSERT_EQ(run_scenario_file(dd_cfg, "--runs 20 --jobs 2 --quiet --no-plots", dd, dd_log), 0) << slurp(dd_log);
  const YAML::Node dd_ekf = YAML::LoadFile((dd / "summary.json").string())["filters"]["ekf"];
  EXPECT_GE(dd_ekf["nees_mean"]["mean"].as<double>(), 12.0);
  EXPECT_LE(dd_ekf["nees_mean"]["mean"].as<double>(), 18.3);
  EXPECT_LE(metric_median(dd_ekf["attitude_max_deg"]), 3e-3);
  EXPECT_LE(metric_median(dd_ekf["rate_max_dps"]), 2e-5);
  fs::remove(dd_log);
  fs::remove(dd_cfg);
  fs::remove_all(dd);
}

// An orbit of radius 1000 m (inside the Earth) makes the truth non-finite within seconds:
// exit 4 at the first non-finite sample, naming it.
TEST(GpsInsScenarios, NonFiniteTruthExitsFourNamingSampleAndQuantity) {
  expect_non_finite_truth_exit_four("gps_ins", "gps-ins-flyaround", {{"radius: 6899807", "radius: 1000"}, kNoTable1},
                                    "--duration 100",
                                    "gps_ins: the truth became non-finite at sample 4 (t = 4 s): relative position (m)");
}
