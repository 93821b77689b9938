// Metrics on synthetic error series with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "hinf/sim/metrics.hpp"
#include "hinf/sim/plots.hpp"

namespace {

using hinf::sim::compute_metrics;
using hinf::sim::compute_stats;
using hinf::sim::MetricSettings;

TEST(Metrics, KnownSeries) {
  // t = 0..9 s; position error 10 − t for t < 5, then alternating 0.3 / 0.4; velocity 0.1·k
  std::vector<double> t, p, v;
  for (int k = 0; k < 10; ++k) {
    t.push_back(k);
    p.push_back(k < 5 ? 10.0 - k : (k % 2 ? 0.3 : 0.4));
    v.push_back(0.1 * k);
  }
  MetricSettings s;
  s.steady_state_start_s = 5.0;
  s.converge_threshold_m = 1.0;
  const auto m = compute_metrics(t, p, v, std::nullopt, s);
  ASSERT_TRUE(m.position_rms_m && m.velocity_rms_mps && m.position_max_m && m.converge_time_s);
  // window k = 5..9: p = 0.3, 0.4, 0.3, 0.4, 0.3
  EXPECT_NEAR(*m.position_rms_m, std::sqrt((3 * 0.09 + 2 * 0.16) / 5), 1e-15);
  EXPECT_NEAR(*m.velocity_rms_mps, std::sqrt((0.25 + 0.36 + 0.49 + 0.64 + 0.81) / 5), 1e-15);
  EXPECT_DOUBLE_EQ(*m.position_max_m, 0.4);
  EXPECT_DOUBLE_EQ(*m.converge_time_s, 5.0);  // p(4) = 6 ≥ 1, from k = 5 all < 1
  EXPECT_FALSE(m.diverged);
}

TEST(Metrics, ConvergenceIsFromTheLastExcursion) {
  std::vector<double> t = {0, 1, 2, 3, 4, 5}, p = {5, 0.5, 0.5, 2, 0.5, 0.5}, v(6, 0.0);
  MetricSettings s;
  s.converge_threshold_m = 1.0;
  EXPECT_DOUBLE_EQ(*compute_metrics(t, p, v, std::nullopt, s).converge_time_s, 4.0);
  p.back() = 1.0;  // threshold is strict: error must stay *below* it
  EXPECT_FALSE(compute_metrics(t, p, v, std::nullopt, s).converge_time_s.has_value());
}

TEST(Metrics, WindowedConvergenceIgnoresAnIsolatedOutlier) {
  // t = 0..19 s, error 5 m until t = 3, then 0.2 m with one 3 m outlier at t = 12.
  std::vector<double> t, p, v(20, 0.0);
  for (int k = 0; k < 20; ++k) {
    t.push_back(k);
    p.push_back(k <= 3 ? 5.0 : (k == 12 ? 3.0 : 0.2));
  }
  MetricSettings s;
  s.converge_threshold_m = 1.0;
  auto m = compute_metrics(t, p, v, std::nullopt, s);  // no window: from the sample after the outlier
  EXPECT_DOUBLE_EQ(*m.converge_time_s, 13.0);
  EXPECT_DOUBLE_EQ(*m.converge_time_pointwise_s, 13.0);
  s.converge_window_s = 10.0;  // trailing window (t − 10, t]: ten samples
  m = compute_metrics(t, p, v, std::nullopt, s);
  EXPECT_DOUBLE_EQ(*m.converge_time_pointwise_s, 13.0);
  // t = 12: samples 3..12 = 5, 0.2 ×8, 3 → RMS sqrt((25 + 0.32 + 9)/10) = 1.85 ≥ 1;
  // t = 13..19: samples 0.2 ×9 and 3 → sqrt((0.36 + 9)/10) = 0.967 < 1.
  EXPECT_DOUBLE_EQ(*m.converge_time_s, 13.0);
  s.converge_window_s = 20.0;  // whole history: the initial 5 m samples keep it above 1 until
  // sum/(k+1) < 1: (100 + 9 + 0.04·(k − 4)) / (k + 1) < 1 never holds for k ≤ 19 → none
  m = compute_metrics(t, p, v, std::nullopt, s);
  EXPECT_FALSE(m.converge_time_s.has_value());
  EXPECT_DOUBLE_EQ(*m.converge_time_pointwise_s, 13.0);
  // Outlier of 2 m and a 5 s window (five samples): t = 7 still holds the 5 m sample
  // (sqrt((25 + 0.16)/5) = 2.24); from t = 8 every window is below 1, the outlier's worst
  // (t = 12..16: 0.2 ×4 and 2) sqrt((0.16 + 4)/5) = 0.912 — converged at 8 although the
  // pointwise error only settles at 13.
  p[12] = 2.0;
  s.converge_window_s = 5.0;
  m = compute_metrics(t, p, v, std::nullopt, s);
  EXPECT_DOUBLE_EQ(*m.converge_time_s, 8.0);
  EXPECT_DOUBLE_EQ(*m.converge_time_pointwise_s, 13.0);
}

TEST(Metrics, DivergedHasNoMetrics) {
  std::vector<double> t = {0, 1, 2}, p = {1, 2, 3}, v = {0, 0, 0};
  const auto m = compute_metrics(t, p, v, 1L, MetricSettings{});
  EXPECT_TRUE(m.diverged);
  EXPECT_DOUBLE_EQ(*m.diverged_at_s, 1.0);
  EXPECT_FALSE(m.position_rms_m || m.velocity_rms_mps || m.position_max_m || m.converge_time_s);
}

TEST(Metrics, StatsSkipMissingAndUseSampleStd) {
  const auto s = compute_stats({1.0, std::nullopt, 2.0, 3.0, 6.0});
  EXPECT_EQ(s.count, 4);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_NEAR(s.std, std::sqrt((4 + 1 + 0 + 9) / 3.0), 1e-15);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 6.0);
  EXPECT_EQ(compute_stats({std::nullopt}).count, 0);
}

// Three copies of 0.1 sum to 0.30000000000000004: the mean of identical values is the value and
// their spread exactly zero, not the rounding of a sum.
TEST(Metrics, StatsOfIdenticalValuesAreExact) {
  const auto s = compute_stats({0.1, 0.1, 0.1});
  EXPECT_EQ(s.mean, 0.1);
  EXPECT_EQ(s.std, 0.0);
  EXPECT_EQ(s.count, 3);
}

// The plots' moving RMS (docs/experiments.md "Plots"): a window of w seconds (w samples at unit
// spacing; fewer at the start), taken every stride-th sample, NaN from the first NaN on; its
// closed forms on a step and a constant.
TEST(Metrics, MovingRmsOfAStepAndOfAConstant) {
  const auto times = [](std::size_t n) {
    std::vector<double> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k);
    return t;
  };
  const std::vector<double> step{0, 0, 3, 3, 3, 3};
  const std::vector<double> r = hinf::sim::moving_rms_samples(times(6), step, 2, 1);
  ASSERT_EQ(r.size(), 6u);
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 0.0);
  EXPECT_NEAR(r[2], std::sqrt(9.0 / 2), 1e-15);  // {0, 3}
  EXPECT_NEAR(r[3], 3.0, 1e-15);                  // {3, 3}
  const std::vector<double> every2 = hinf::sim::moving_rms_samples(times(6), step, 2, 2);
  ASSERT_EQ(every2.size(), 3u);  // samples 0, 2, 4
  EXPECT_NEAR(every2[2], 3.0, 1e-15);
  const std::vector<double> c = hinf::sim::moving_rms_samples(times(100), std::vector<double>(100, -2.0), 10, 7);
  for (double v : c) EXPECT_NEAR(v, 2.0, 1e-14);
  const std::vector<double> diverged = hinf::sim::moving_rms_samples(times(4), {1, 1, std::nan(""), 1}, 1, 1);
  EXPECT_EQ(diverged[1], 1.0);
  EXPECT_TRUE(std::isnan(diverged[2]) && std::isnan(diverged[3]));
}

// The plots' band over the runs: nearest-rank 5 %, 50 %, 95 % of the runs' values that are not
// NaN at each instant (20 runs valued 1…20: the 1st, 10th and 19th), NaN where all are.
TEST(Metrics, TraceBandIsTheRunsQuantilesPerInstant) {
  std::vector<std::vector<double>> runs;
  for (int r = 1; r <= 20; ++r) runs.push_back({static_cast<double>(r), r == 3 ? std::nan("") : 1.0, std::nan("")});
  std::vector<const std::vector<double>*> pointers;
  for (const auto& r : runs) pointers.push_back(&r);
  const hinf::sim::TraceBand b = hinf::sim::trace_band(pointers);
  ASSERT_EQ(b.median.size(), 3u);
  EXPECT_EQ(b.p05[0], 1.0);
  EXPECT_EQ(b.median[0], 10.0);
  EXPECT_EQ(b.p95[0], 19.0);
  EXPECT_EQ(b.p05[1], 1.0);  // 19 values, the NaN run left out
  EXPECT_EQ(b.p95[1], 1.0);
  EXPECT_TRUE(std::isnan(b.median[2]));
}

// A stream family's traces of one run (run_traces): at most kPlotTracePoints instants, those of
// the filter with the most samples; per filter and norm the moving RMS there (a constant norm c:
// c; a norm that steps from 0 to 4 at t = 1000 with a 10 s window: 0 before, 4 from t = 1010);
// a filter that stopped after 500 samples (gyroless's stopped filter) padded with NaN, and a
// norm that became NaN (a diverged filter) NaN from there on.
TEST(Metrics, RunTracesOfTwoFiltersOneStoppedAndOneDiverged) {
  const long n = 2000;
  std::vector<double> t(n), constant(n, 2.5), step(n), diverging(n, 1.0);
  for (long k = 0; k < n; ++k) {
    t[static_cast<std::size_t>(k)] = 0.5 * static_cast<double>(k);
    step[static_cast<std::size_t>(k)] = t[static_cast<std::size_t>(k)] < 1000 ? 0.0 : 4.0;
  }
  for (long k = 1500; k < n; ++k) diverging[static_cast<std::size_t>(k)] = std::nan("");
  const std::vector<double> stopped_t(t.begin(), t.begin() + 500);
  const std::vector<double> stopped(500, 3.0);
  const hinf::sim::RunTraces r =
      hinf::sim::run_traces({stopped_t, t}, {{stopped, stopped}, {constant, step, diverging}}, 10.0);
  const long stride = (n + hinf::sim::kPlotTracePoints - 1) / hinf::sim::kPlotTracePoints;  // 4
  ASSERT_EQ(static_cast<long>(r.t.size()), (n + stride - 1) / stride);
  ASSERT_LE(static_cast<long>(r.t.size()), hinf::sim::kPlotTracePoints);
  ASSERT_EQ(r.rms.size(), 2u);
  ASSERT_EQ(r.rms[0].size(), 2u);
  ASSERT_EQ(r.rms[1].size(), 3u);
  for (std::size_t j = 0; j < r.t.size(); ++j) {
    EXPECT_EQ(r.t[j], 0.5 * static_cast<double>(j) * stride);
    EXPECT_NEAR(r.rms[1][0][j], 2.5, 1e-14);
    if (r.t[j] < 1000) EXPECT_EQ(r.rms[1][1][j], 0.0) << r.t[j];
    if (r.t[j] >= 1010) EXPECT_NEAR(r.rms[1][1][j], 4.0, 1e-14) << r.t[j];
    if (r.t[j] < 750) EXPECT_NEAR(r.rms[1][2][j], 1.0, 1e-14) << r.t[j];
    else EXPECT_TRUE(std::isnan(r.rms[1][2][j])) << r.t[j];
    if (r.t[j] < 250) EXPECT_NEAR(r.rms[0][0][j], 3.0, 1e-14) << r.t[j];
    else EXPECT_TRUE(std::isnan(r.rms[0][1][j])) << r.t[j];
  }
}

}  // namespace
