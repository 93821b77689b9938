// End-to-end: hinf-sim on the manoeuvring_target scenarios (seed 001, docs/experiments.md),
// checked from their output files only:
//  - the shipped case 6.1 runs and writes its files and plots; summary.json's window metrics,
//    coverages and settle times agree with trajectory.csv (recomputed here) and runs.csv;
//  - the same seed gives the same files with one job or two; several runs give
//    {mean, std, min, max, count} with per-axis arrays;
//  - 001-E1, E2, E5: the noise-free mean response of cases 6.1 and 6.2;
//  - the eccentric variant: freezing costs little, ignoring the eccentricity (CW) much more;
//  - a chaser with its own manoeuvre: the prediction with its command removes the lag;
//  - invalid input: exit 2 naming the key, nothing written;
//  - (heavy) 001-E3, E4, E6: 100-run Monte Carlo of both cases and of the detector.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "sim_cli_test.hpp"

namespace fs = std::filesystem;
using namespace sim_cli_test;

namespace {
const char* const kFree = "manoeuvring-target-chaser-free";
const char* const kMimics = "manoeuvring-target-chaser-mimics";
fs::path fresh_dir(const std::string& name) { return sim_cli_test::fresh_dir("manoeuvring", name); }
const char* const kAxes[3] = {"x", "y", "z"};

// Runs the scenario file with ARGS into a fresh OUT; the exit code, its log printed on failure.
int run_file(const fs::path& cfg, const std::string& args, const fs::path& out) {
  const fs::path log = out.string() + ".log";
  const int rc = run_scenario_file(cfg, args + " --quiet", out, log);
  if (rc != 0) std::cerr << slurp(log);
  fs::remove(log);
  return rc;
}

// The noise-free variant of a shipped case, run once; its trajectory.
Columns mean_response(const char* name, const fs::path& out) {
  const fs::path cfg = edited_scenario(name, "noiseless", {{"noise: true ", "noise: false"}});
  EXPECT_EQ(run_file(cfg, "--no-plots", out), 0);
  fs::remove(cfg);
  return read_csv(out / "trajectory.csv");
}

double u_error(const Columns& tr, const std::vector<double>& row, int axis, const std::string& filter = "transient") {
  return row[static_cast<std::size_t>(tr.col(filter + "_uhat_" + kAxes[axis]))] -
         row[static_cast<std::size_t>(tr.col(std::string("true_u") + kAxes[axis]))];
}

double position_error(const Columns& tr, const std::vector<double>& row, const std::string& filter = "transient") {
  double s = 0;
  for (int i = 0; i < 3; ++i) {
    const double e = row[static_cast<std::size_t>(tr.col(filter + "_est_" + kAxes[i]))] -
                     row[static_cast<std::size_t>(tr.col(std::string("true_") + kAxes[i]))];
    s += e * e;
  }
  return std::sqrt(s);
}

// The largest |Û − U| on axis over the samples tagged in [from, to).
double max_u_error(const Columns& tr, int axis, double from, double to) {
  double m = 0;
  for (const auto& row : tr.rows) {
    const double t = row[static_cast<std::size_t>(tr.col("u_time"))];
    if (t >= from && t < to) m = std::max(m, std::abs(u_error(tr, row, axis)));
  }
  return m;
}
}  // namespace

// Case 6.1, one run: the files, and the summary recomputed from trajectory.csv.
TEST(ManoeuvringScenario, RunsAndSummaryMatchesTrajectory) {
  const fs::path out = fresh_dir("brief");
  ASSERT_EQ(run_scenario(kFree, "", out), 0);
  for (const char* f : {"trajectory.csv", "runs.csv", "summary.json"}) EXPECT_TRUE(fs::exists(out / f)) << f;
  for (const char* png : {"transient_position_error.png", "transient_velocity_error.png", "transient_manoeuvre_error.png",
                          "error_norms.png"})
    EXPECT_EQ(slurp(out / png).substr(0, 8), "\x89PNG\r\n\x1a\n") << png;
  const YAML::Node summary = YAML::LoadFile((out / "summary.json").string());
  EXPECT_EQ(summary["scenario_family"].as<std::string>(), "manoeuvring_target");
  const YAML::Node f = summary["filters"]["transient"];
  EXPECT_NEAR(f["detector"]["threshold"].as<double>(), 59.703, 1e-3);  // χ²₃₀ at 1 − 10⁻³
  const Columns tr = read_csv(out / "trajectory.csv");
  ASSERT_EQ(tr.rows.size(), 1000u);
  const auto at = [&](const std::vector<double>& row, const std::string& c) { return row[static_cast<std::size_t>(tr.col(c))]; };
  const std::vector<std::tuple<std::string, double, double>> windows{{"pre", 50, 300}, {"manoeuvre", 360, 600}, {"post", 660, 1000}};
  for (const auto& [name, from, to] : windows) {
    const YAML::Node w = f["windows"][name];
    for (int i = 0; i < 3; ++i) {
      const std::string a = kAxes[i];
      double pos = 0, umean = 0, usq = 0, cover = 0, n = 0;
      for (const auto& row : tr.rows) {
        if (at(row, "u_time") < from || at(row, "u_time") >= to) continue;
        const double pe = at(row, "transient_est_" + a) - at(row, "true_" + a);
        const double ue = u_error(tr, row, i);
        pos += pe * pe, umean += ue, usq += ue * ue, n += 1;
        cover += std::abs(ue) <= 3 * std::sqrt(at(row, "transient_uvar_innov_" + a)) ? 1 : 0;
      }
      ASSERT_GT(n, 0);
      EXPECT_NEAR(w["position_rms_m"][i].as<double>(), std::sqrt(pos / n), 1e-9 * std::sqrt(pos / n)) << name << a;
      EXPECT_NEAR(w["maneuver_error_mean_mps2"][i].as<double>(), umean / n, 1e-12) << name << a;
      EXPECT_NEAR(w["maneuver_error_rms_mps2"][i].as<double>(), std::sqrt(usq / n), 1e-9 * std::sqrt(usq / n)) << name << a;
      EXPECT_NEAR(w["coverage_3sigma_innovation"][i].as<double>(), cover / n, 1e-12) << name << a;
      EXPECT_EQ(w["samples"].as<double>(), n) << name;
    }
  }
  // the settle time after the offset on x, recomputed: the first tag from which |Û − U| ≤ 0.05 holds to the end
  double settled = -1;
  for (const auto& row : tr.rows) {
    const double t = at(row, "u_time");
    if (t < 600) continue;
    if (std::abs(u_error(tr, row, 0)) > 0.05) settled = -1;
    else if (settled < 0) settled = t - 600;
  }
  if (settled < 0) EXPECT_TRUE(f["settle_after_offset_s"][0].IsNull());
  else EXPECT_EQ(f["settle_after_offset_s"][0].as<double>(), settled);
  // runs.csv holds the same numbers
  const Columns runs = read_csv(out / "runs.csv");
  ASSERT_EQ(runs.rows.size(), 1u);
  EXPECT_EQ(runs.rows[0][static_cast<std::size_t>(runs.col("manoeuvre_position_rms_m_x"))],
            f["windows"]["manoeuvre"]["position_rms_m"][0].as<double>());
  // the true manoeuvre in LVLH0: the target's own-LVLH thrust turned by the frames' angle
  const auto& mid = tr.rows[400];
  EXPECT_NEAR(at(mid, "true_ux"), 0.496, 1e-3);
  EXPECT_NEAR(at(mid, "true_uy"), 0.504, 1e-3);
  EXPECT_EQ(at(tr.rows[700], "true_ux"), 0.0);
}

TEST(ManoeuvringScenario, SameSeedSameFilesWithOneOrTwoJobsAndStatisticsOverRuns) {
  const fs::path a = fresh_dir("jobs1"), b = fresh_dir("jobs2");
  ASSERT_EQ(run_scenario(kMimics, "--duration 400 --runs 4 --jobs 1 --seed 7 --no-plots", a), 0);
  ASSERT_EQ(run_scenario(kMimics, "--duration 400 --runs 4 --jobs 2 --seed 7 --no-plots", b), 0);
  for (const char* f : {"trajectory.csv", "runs.csv", "summary.json"}) EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
  const YAML::Node f = YAML::LoadFile((a / "summary.json").string())["filters"]["transient"];
  const YAML::Node rms = f["windows"]["pre"]["position_rms_m"];
  for (const char* k : {"mean", "std", "min", "max", "count"}) {
    ASSERT_TRUE(rms[k].IsSequence()) << k;
    EXPECT_EQ(rms[k].size(), 3u) << k;
  }
  EXPECT_EQ(rms["count"][0].as<int>(), 4);
  EXPECT_LE(rms["min"][1].as<double>(), rms["mean"][1].as<double>());
  EXPECT_TRUE(f["final_position_error_m"]["mean"].IsScalar());
  // a window past the shortened end has no samples: its metrics are null, not made up
  EXPECT_TRUE(f["windows"]["post"]["position_rms_m"]["mean"][0].IsNull());
  EXPECT_FALSE(fs::exists(a / "transient_position_error.png"));
}

// 001-E1 and E5: case 6.1 without noise.
TEST(ManoeuvringScenario, MeanResponseOfCaseChaserFree) {
  const Columns tr = mean_response(kFree, fresh_dir("e1"));
  ASSERT_EQ(tr.rows.size(), 1000u);
  EXPECT_LE(max_u_error(tr, 0, 300 + 35, 600), 0.05);
  EXPECT_LE(max_u_error(tr, 1, 300 + 15, 600), 0.05);
  EXPECT_LE(max_u_error(tr, 0, 600 + 35, 1000), 0.05);
  EXPECT_LE(max_u_error(tr, 1, 600 + 25, 1000), 0.05);
  EXPECT_LE(max_u_error(tr, 0, 450, 600), 0.025);
  EXPECT_LE(max_u_error(tr, 1, 450, 600), 0.025);
  EXPECT_GT(max_u_error(tr, 0, 300, 310), 0.1);  // the onset is not instantaneous: the check can fail
  double pre = 0, post = 0;
  for (const auto& row : tr.rows) {
    const double t = row[0];
    if (t < 300) pre = std::max(pre, position_error(tr, row));
    if (t >= 660) post = std::max(post, position_error(tr, row));
  }
  EXPECT_LE(pre, 0.5);
  EXPECT_GT(post, pre);  // E5: the weak bias grows with the separation …
  EXPECT_LE(position_error(tr, tr.rows.back()), 10.0);  // … and stays bounded
}

// 001-E2: case 6.2 without noise: the relative manoeuvre is all but zero.
TEST(ManoeuvringScenario, MeanResponseOfCaseChaserMimics) {
  const Columns tr = mean_response(kMimics, fresh_dir("e2"));
  for (int i = 0; i < 3; ++i) EXPECT_LE(max_u_error(tr, i, 0, 1000), 0.005) << kAxes[i];
  double worst = 0;
  for (const auto& row : tr.rows) worst = std::max(worst, position_error(tr, row));
  EXPECT_LE(worst, 1.0);
}

// The eccentric variant (no noise): the frozen transition against the exact one, and CW.
TEST(ManoeuvringScenario, EccentricOrbitFreezingCostsLittleAndCwMuch) {
  const fs::path out = fresh_dir("eccentric");
  ASSERT_EQ(run_scenario("manoeuvring-target-eccentric", "--no-plots", out), 0);
  const Columns tr = read_csv(out / "trajectory.csv");
  double frozen = 0, exact = 0, cw = 0, du = 0;
  for (const auto& row : tr.rows) {
    frozen = std::max(frozen, position_error(tr, row, "frozen"));
    exact = std::max(exact, position_error(tr, row, "exact"));
    cw = std::max(cw, position_error(tr, row, "cw"));
    for (int i = 0; i < 3; ++i) du = std::max(du, std::abs(u_error(tr, row, i, "frozen") - u_error(tr, row, i, "exact")));
  }
  EXPECT_LE(std::abs(frozen - exact), 0.01 * exact);
  EXPECT_LE(du, 1e-3);  // m/s²: the freezing's share of the manoeuvre error
  EXPECT_GE(cw, frozen);
  const YAML::Node f = YAML::LoadFile((out / "summary.json").string())["filters"];
  EXPECT_GE(f["cw"]["windows"]["post"]["position_rms_m"][1].as<double>(),
            5 * f["frozen"]["windows"]["post"]["position_rms_m"][1].as<double>());
}

// The chaser flying its own manoeuvre (noise off): the source's unforced prediction lags while
// the chaser thrusts; carrying its known command in the prediction removes the lag.
TEST(ManoeuvringScenario, PredictionWithTheChaserCommandRemovesTheLag) {
  const fs::path cfg = edited_scenario("manoeuvring-target-chaser-differs", "noiseless", {{"noise: true ", "noise: false"}});
  const fs::path out = fresh_dir("differs");
  ASSERT_EQ(run_file(cfg, "--no-plots", out), 0);
  fs::remove(cfg);
  const YAML::Node f = YAML::LoadFile((out / "summary.json").string())["filters"];
  const auto metric = [&](const char* filter, const char* window, const char* name) {
    return f[filter]["windows"][window][name][0].as<double>();
  };
  // before the target's onset only the chaser thrusts (from 200 s): all lag, no Û error
  EXPECT_LE(metric("with_control", "pre", "position_rms_m"), 0.1 * metric("transient", "pre", "position_rms_m"));
  EXPECT_GE(metric("transient", "pre", "position_rms_m"), 5.0);
  EXPECT_LE(metric("with_control", "manoeuvre", "maneuver_error_rms_mps2"),
            0.5 * metric("transient", "manoeuvre", "maneuver_error_rms_mps2"));
  EXPECT_LE(metric("with_control", "manoeuvre", "position_rms_m"), 0.6 * metric("transient", "manoeuvre", "position_rms_m"));
}

TEST(ManoeuvringScenario, InvalidValuesExitTwoNamingTheKey) {
  const std::vector<InvalidCase> cases{
      {"e: 0.0, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.5",
       "e: 1.0, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.5", "orbits.target.e"},
      {"e: 0.0, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.0",
       "e: 1.5, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.0", "orbits.chaser.e"},
      {"e: 0.0, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.0",
       "e: 0.1, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.0", "orbits.chaser.e"},
      {"e: 0.0, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.5",
       "e: -0.1, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.5", "orbits.target.e"},
      {"a: 6688.137e3", "a: 6000.0e3", "orbits.target.a"},
      {"a: 6678.137e3", "a: -6678.137e3", "orbits.chaser.a"},
      {"a: 6678.137e3", "a: 1.0e300", "orbits.chaser.a"},
      {"true_anomaly_deg: 315.5}", "true_anomaly_deg: .nan}", "orbits.target.true_anomaly_deg"},
      {"true_anomaly_deg: 315.5}", "true_anomaly_deg: 315.0}\n  chas: {}", "chas"},
      {"a: 6688.137e3, e: 0.0, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.5",
       "a: 6678.137e3, e: 0.0, inclination_deg: 28.5, raan_deg: 45.0, arg_perigee_deg: 0.0, true_anomaly_deg: 315.0",
       "orbits"},  // target == chaser: no line of sight
      {"start: 300, end: 600", "start: 300, end: 1600", "manoeuvres.target[0].end"},
      {"start: 300, end: 600", "start: 1300, end: 1600", "manoeuvres.target[0].start"},
      {"start: 300, end: 600", "start: 300, end: 200", "manoeuvres.target[0].end"},
      {"start: 300, end: 600", "start: -10, end: 600", "manoeuvres.target[0].start"},
      {"frame: own_lvlh, accel: [0.5, 0.5, 0.0]}]", "frame: body, accel: [0.5, 0.5, 0.0]}]", "frame"},
      {"accel: [0.5, 0.5, 0.0]}]", "accel: [0.5, 0.5]}]", "accel"},
      {"pre: [50, 300]", "pre: [300, 50]", "metrics.windows.pre"},
      {"post: [660, 1000]", "post: [660, 1001]", "metrics.windows.post"},
      {"pre: [50, 300]", "Pre: [50, 300]", "Pre"},
      {"maneuver_tolerance: 0.05", "maneuver_tolerance: 0", "maneuver_tolerance"},
      {"transition: frozen ", "transition: magnus ", "transition"},
      {"process_noise_psd: 0.25", "process_noise_psd: -0.25", "process_noise_psd"},
      {"maneuver_covariance: both", "maneuver_covariance: neither", "maneuver_covariance"},
      {"window: 10, p_false_alarm: 1.0e-3", "window: 0, p_false_alarm: 1.0e-3", "detector.window"},
      {"window: 10, p_false_alarm: 1.0e-3", "window: 10, p_false_alarm: 1.5", "p_false_alarm"},
      {"type: nis_window", "type: glr", "detector.type"},
      {"predict_with_chaser_control: false", "predict_with_chaser_control: perhaps", "predict_with_chaser_control"},
      {"convention: z_up", "convention: sideways", "convention"},
      {"range: {type: gaussian, sigma: 1.0}", "range: {type: gaussian, sigma: 0}", "measurement.range.sigma"},
      {"azimuth: {type: gaussian, sigma: 1.0e-3}", "azimuth: {type: laplace, sigma: 1.0e-3}", "azimuth.type"},
      {"position_sigma: 0.0", "position_sigma: -1.0", "position_sigma"},
      {"initial_error_sigma: [1, 1, 1, 0.1, 0.1, 0.1]", "initial_error_sigma: [1, 1, 1, 0.1, 0.1]", "initial_error_sigma"},
      {"  sigma: [1, 1, 1, 0.1, 0.1, 0.1] ", "  sigma: [1, 1, 1, 0.1, 0.1, 0] ", "estimate.sigma"},
      {"transient:", "Transient:", "Transient"},
      {"duration: 1000 ", "duration: 1000.5 ", "duration"},
      {"mu: 3.986004418e14", "mu: 0", "mu"},
      {"noise: true ", "noise: on ", "noise"},
  };
  expect_invalid_values_exit_two("manoeuvring", kFree, cases);
}

// 001-E3 and E4: 100 runs of each case (seed 1).
TEST(ManoeuvringAcceptance, HundredRunsOfBothCases) {
  const fs::path free = fresh_dir("mc_free"), mimics = fresh_dir("mc_mimics");
  ASSERT_EQ(run_scenario(kFree, "--runs 100 --jobs 2 --no-plots", free), 0);
  ASSERT_EQ(run_scenario(kMimics, "--runs 100 --jobs 2 --no-plots", mimics), 0);
  const YAML::Node f = YAML::LoadFile((free / "summary.json").string())["filters"]["transient"]["windows"];
  const YAML::Node g = YAML::LoadFile((mimics / "summary.json").string())["filters"]["transient"]["windows"];
  const Columns runs = read_csv(free / "runs.csv");
  ASSERT_EQ(runs.rows.size(), 100u);
  for (int i = 0; i < 3; ++i) {
    const std::string a = kAxes[i];
    // E3: the per-run mean manoeuvre error in [360, 600) is small in every run
    EXPECT_LE(f["manoeuvre"]["maneuver_error_mean_mps2"]["max"][i].as<double>(), 0.05) << a;
    EXPECT_GE(f["manoeuvre"]["maneuver_error_mean_mps2"]["min"][i].as<double>(), -0.05) << a;
    // E3: the ensemble RMS of the error is the innovation form's σ within ±20 %
    double err2 = 0, var = 0;
    for (const auto& row : runs.rows) {
      err2 += std::pow(row[static_cast<std::size_t>(runs.col("manoeuvre_maneuver_error_rms_mps2_" + a))], 2);
      var += std::pow(row[static_cast<std::size_t>(runs.col("manoeuvre_maneuver_sigma_innovation_mps2_" + a))], 2);
    }
    const double ratio = std::sqrt(err2 / var);
    EXPECT_GE(ratio, 0.8) << a;
    EXPECT_LE(ratio, 1.2) << a;
    // E3: (7b)'s 3σ covers the error
    EXPECT_GE(f["manoeuvre"]["coverage_3sigma_paper"]["min"][i].as<double>(), 0.997) << a;
  }
  // E3: the pre-window position RMS
  const double limit[3] = {25, 5, 25};
  for (int i = 0; i < 3; ++i) EXPECT_LE(f["pre"]["position_rms_m"]["mean"][i].as<double>(), limit[i]) << kAxes[i];
  // E4: the chaser mimicking the target: the manoeuvre window is hardly worse than before it
  const double free_x = f["manoeuvre"]["position_rms_m"]["mean"][0].as<double>();
  const double mimic_x = g["manoeuvre"]["position_rms_m"]["mean"][0].as<double>();
  EXPECT_LE(mimic_x, 0.6 * free_x);
  EXPECT_LE(mimic_x, 1.3 * g["pre"]["position_rms_m"]["mean"][0].as<double>());
}

// 001-E6: the windowed-NIS detector at q = 0.0225 m²/s³, w = 10, P_FA = 1e-3, 100 runs.
TEST(ManoeuvringAcceptance, DetectorFindsTheOnsetQuickly) {
  const fs::path cfg = edited_scenario(kFree, "detector", {{"process_noise_psd: 0.25", "process_noise_psd: 0.0225"}});
  const fs::path out = fresh_dir("detector");
  ASSERT_EQ(run_file(cfg, "--runs 100 --jobs 2 --no-plots", out), 0);
  fs::remove(cfg);
  const Columns runs = read_csv(out / "runs.csv");
  std::vector<double> delay;
  double false_alarms = 0;
  for (const auto& row : runs.rows) {
    const double d = row[static_cast<std::size_t>(runs.col("detection_delay_s"))];
    if (std::isfinite(d)) delay.push_back(d);
    false_alarms += row[static_cast<std::size_t>(runs.col("false_alarm_rate"))];
  }
  ASSERT_EQ(delay.size(), 100u);  // every run detects
  std::sort(delay.begin(), delay.end());
  EXPECT_LE(0.5 * (delay[49] + delay[50]), 12.0);
  EXPECT_LE(delay.back(), 20.0);
  EXPECT_LE(false_alarms / 100, 2e-3);
}

// A target thrust of 1e308 m/s² from 300 s overflows its orbit: exit 4 at the first
// non-finite sample, naming it.
TEST(ManoeuvringScenario, NonFiniteTruthExitsFourNamingSampleAndQuantity) {
  expect_non_finite_truth_exit_four(
      "manoeuvring", "manoeuvring-target-chaser-free",
      {{"accel: [0.5, 0.5, 0.0]}]", "accel: [1e308, 0.5, 0.0]}]"}}, "--duration 400",
      "manoeuvring_target: the truth became non-finite at sample 301 (t = 301 s): target position (ECI, m) = [nan");
}
