// hinf-sim's end-of-run table (sim/summary_table.hpp) from hand-written summaries: one run's
// numbers, mean ± std over runs, the outcome column, RMS figures first, per-axis variants left
// out, a summary without filters or metrics giving no table.
#include <gtest/gtest.h>

#include <string>

#include "hinf/sim/summary_table.hpp"

namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SummaryTable, OneRunShowsItsNumbersAndOutcome) {
  const std::string t = hinf::sim::summary_table(
      R"({"filters": {"hinf": {"position_max_m": 0.8, "position_rms_m": 0.34, "converged": true, "diverged": false},
                      "ekf": {"position_max_m": 9, "position_rms_m": 1e3, "converged": false, "diverged": true,
                              "diverged_at_s": 12.5}}})");
  EXPECT_LT(t.find("position_rms_m"), t.find("position_max_m")) << t;  // RMS first
  EXPECT_NE(t.find("hinf"), std::string::npos);
  EXPECT_NE(t.find("0.34"), std::string::npos) << t;
  EXPECT_NE(t.find("converged"), std::string::npos);
  EXPECT_NE(t.find("DIVERGED at 12.5 s"), std::string::npos) << t;
  EXPECT_EQ(count(t, "\n"), 3);  // header and two rows
}

TEST(SummaryTable, SeveralRunsShowMeanAndStd) {
  const std::string t = hinf::sim::summary_table(
      R"({"filters": {"rekf": {"attitude_rms_deg": {"mean": 0.5, "std": 0.25, "min": 0.1, "max": 1, "count": 3},
                               "attitude_rms_deg_roll": {"mean": 0.1, "std": 0.1, "min": 0, "max": 0.3, "count": 3},
                               "diverged_runs": 1}}})");
  EXPECT_NE(t.find("0.5 ± 0.25"), std::string::npos) << t;
  EXPECT_EQ(t.find("attitude_rms_deg_roll"), std::string::npos) << t;  // a per-axis variant of one shown
  EXPECT_NE(t.find("1 runs diverged"), std::string::npos) << t;
}

TEST(SummaryTable, ControllerMetricsOrNothing) {
  EXPECT_NE(hinf::sim::summary_table(R"({"metrics": {"position_rms_m": 0.0033}})").find("controller"), std::string::npos);
  EXPECT_EQ(hinf::sim::summary_table(R"({"format": "hinf-sim-summary/1"})"), "");
}

}  // namespace

namespace {

// A family that names its headline metrics gets those columns, in its order, and no others
// (linear_plant: the measured RMS beside the predicted one, not its δ columns or γ).
TEST(SummaryTable, TheFamilysHeadlineMetricsWhenItNamesThem) {
  const std::string t = hinf::sim::summary_table(
      R"({"headline_metrics": ["error_rms", "predicted_error_rms", "error_max"],
          "filters": {"kalman": {"gamma": 1.6, "delta_1": 1, "error_rms": 0.21, "predicted_error_rms": 0.2,
                                 "error_max": 0.9, "diverged": false}}})");
  EXPECT_EQ(t.find("gamma"), std::string::npos) << t;
  EXPECT_EQ(t.find("delta_1"), std::string::npos) << t;
  EXPECT_LT(t.find("error_rms"), t.find("predicted_error_rms")) << t;
  EXPECT_LT(t.find("predicted_error_rms"), t.find("error_max")) << t;
  EXPECT_NE(t.find("0.21"), std::string::npos) << t;
}

}  // namespace

namespace {

// A metric whose statistics over the runs are lists (the manoeuvring family's settling time per
// manoeuvre) or null (never settled) is no column and never a crash (issue 38: `hinf-sim
// manoeuvring-target-chaser-free.yaml --runs 100`, the README's example, ended "internal error:
// type must be number, but is array", exit 4, once the runs were done).
TEST(SummaryTable, ListsAndNullStatisticsAreNotColumns) {
  std::string t;
  EXPECT_NO_THROW(t = hinf::sim::summary_table(
                      R"({"filters": {"transient": {"settle_after_onset_s": {"mean": [1, 2], "std": [0, 0]},
                                                     "never": {"mean": null, "std": null},
                                                     "detection_delay_s": {"mean": 42, "std": 0}}}})"));
  EXPECT_EQ(t.find("settle_after_onset_s"), std::string::npos) << t;
  EXPECT_EQ(t.find("never"), std::string::npos) << t;
  EXPECT_NE(t.find("42 ± 0"), std::string::npos) << t;
  EXPECT_NO_THROW(hinf::sim::summary_table(
      R"({"headline_metrics": ["never"], "filters": {"f": {"never": {"mean": null, "std": null}}}})"));
}

}  // namespace
