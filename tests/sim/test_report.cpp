// summary.json (format_summary_json): valid JSON read back with nlohmann, keys in the
// documented order, null for absent values, non-finite numbers refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "hinf/sim/report.hpp"

namespace {

using namespace hinf::sim;
using Json = nlohmann::ordered_json;

std::vector<std::string> keys(const Json& j) {
  std::vector<std::string> k;
  for (const auto& item : j.items()) k.push_back(item.key());
  return k;
}

Scenario scenario() {
  Scenario s;
  s.duration = 300;
  s.sample_time = 0.1;
  s.truth_delta = 0.03;
  s.converge_threshold_m = 1.5;
  s.converge_window_s = 10;
  return s;
}

SummaryContext context() {
  SummaryContext ctx;
  ctx.scenario_path = "dir/odd \"name\"\\x.yaml";
  ctx.seed = 18446744073709551615ull;  // the largest seed
  ctx.gains["hinf"] = {"synthesised from configs/paper-dbar0.05.yaml", 0.35872371790363927};
  ctx.gains["published"] = {"gains file configs/paper-published-gains.yaml", std::nullopt};
  return ctx;
}

FilterOutcome converged(const std::string& name, double rms) {
  FilterOutcome o;
  o.name = name;
  o.metrics.position_rms_m = rms;
  o.metrics.velocity_rms_mps = rms / 10;
  o.metrics.position_max_m = 3 * rms;
  o.metrics.converge_time_s = 77.4;
  o.metrics.converge_time_pointwise_s = 65.6;
  return o;
}

FilterOutcome diverged(const std::string& name) {
  FilterOutcome o;
  o.name = name;
  o.metrics.diverged = true;
  o.metrics.diverged_at_s = 12.5;
  o.health.failed_steps = 3;
  o.health.first_failure = "innovation covariance not \"positive\" definite";
  o.health.first_failure_t = 12.4;
  return o;
}

const std::vector<std::string> kTopKeys = {
    "format", "scenario", "seed", "runs", "duration_s", "sample_time_s", "truth_delta",
    "steady_state_start_s", "converge_threshold_m", "converge_window_s", "gains", "filters"};

TEST(SummaryJson, OneRunParsesWithTheKeysInOrder) {
  RunResult run;
  run.filters = {converged("hinf", 1.4970130843508105), diverged("ekf")};
  const std::string text = format_summary_json(scenario(), {run}, context());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.substr(0, 4), "{\n  ");  // dump(2)
  const Json j = Json::parse(text);

  EXPECT_EQ(keys(j), kTopKeys);
  EXPECT_EQ(j["format"], "hinf-sim-summary/1");
  EXPECT_EQ(j["scenario"], "dir/odd \"name\"\\x.yaml");
  EXPECT_EQ(j["seed"].get<std::uint64_t>(), 18446744073709551615ull);
  EXPECT_EQ(j["runs"], 1);
  EXPECT_EQ(j["duration_s"].get<double>(), 300.0);
  EXPECT_EQ(j["sample_time_s"].get<double>(), 0.1);  // round-trips exactly
  EXPECT_EQ(j["truth_delta"].get<double>(), 0.03);
  EXPECT_EQ(j["steady_state_start_s"].get<double>(), 150.0);  // default: half the duration
  EXPECT_EQ(j["converge_threshold_m"].get<double>(), 1.5);
  EXPECT_EQ(j["converge_window_s"].get<double>(), 10.0);

  EXPECT_EQ(keys(j["gains"]), (std::vector<std::string>{"hinf", "published"}));
  EXPECT_EQ(keys(j["gains"]["hinf"]), (std::vector<std::string>{"origin", "gamma"}));
  EXPECT_EQ(j["gains"]["hinf"]["gamma"].get<double>(), 0.35872371790363927);
  EXPECT_TRUE(j["gains"]["published"]["gamma"].is_null());

  EXPECT_EQ(keys(j["filters"]), (std::vector<std::string>{"hinf", "ekf"}));  // run order
  const Json& h = j["filters"]["hinf"];
  EXPECT_EQ(keys(h), (std::vector<std::string>{"position_rms_m", "velocity_rms_mps", "position_max_m",
                                               "converge_time_s", "converge_time_pointwise_s", "converged",
                                               "diverged", "diverged_at_s", "failed_steps"}));
  EXPECT_EQ(h["position_rms_m"].get<double>(), 1.4970130843508105);
  EXPECT_EQ(h["converge_time_s"].get<double>(), 77.4);
  EXPECT_EQ(h["converge_time_pointwise_s"].get<double>(), 65.6);
  EXPECT_EQ(h["converged"], true);
  EXPECT_EQ(h["diverged"], false);
  EXPECT_TRUE(h["diverged_at_s"].is_null());
  EXPECT_EQ(h["failed_steps"], 0);

  const Json& e = j["filters"]["ekf"];
  EXPECT_EQ(keys(e), (std::vector<std::string>{"position_rms_m", "velocity_rms_mps", "position_max_m",
                                               "converge_time_s", "converge_time_pointwise_s", "converged",
                                               "diverged", "diverged_at_s", "failed_steps", "first_failure",
                                               "first_failure_t_s"}));
  for (const char* k : {"position_rms_m", "velocity_rms_mps", "position_max_m", "converge_time_s",
                        "converge_time_pointwise_s"})
    EXPECT_TRUE(e[k].is_null()) << k;
  EXPECT_EQ(e["converged"], false);
  EXPECT_EQ(e["diverged"], true);
  EXPECT_EQ(e["diverged_at_s"].get<double>(), 12.5);
  EXPECT_EQ(e["failed_steps"], 3);
  EXPECT_EQ(e["first_failure"], "innovation covariance not \"positive\" definite");
  EXPECT_EQ(e["first_failure_t_s"].get<double>(), 12.4);
}

TEST(SummaryJson, SeveralRunsGiveStatisticsOverTheRunsThatHaveAValue) {
  std::vector<RunResult> runs(3);
  runs[0].filters = {converged("hinf", 1.0)};
  runs[1].filters = {converged("hinf", 2.0)};
  runs[2].filters = {diverged("hinf")};
  const Json j = Json::parse(format_summary_json(scenario(), runs, context()));
  EXPECT_EQ(keys(j), kTopKeys);
  EXPECT_EQ(j["runs"], 3);
  const Json& h = j["filters"]["hinf"];
  EXPECT_EQ(keys(h), (std::vector<std::string>{"position_rms_m", "velocity_rms_mps", "position_max_m",
                                               "converge_time_s", "converge_time_pointwise_s", "diverged_runs",
                                               "never_converged_runs", "runs_with_failed_steps"}));
  const Json& p = h["position_rms_m"];
  EXPECT_EQ(keys(p), (std::vector<std::string>{"mean", "std", "min", "max", "count"}));
  EXPECT_EQ(p["mean"].get<double>(), 1.5);
  EXPECT_EQ(p["std"].get<double>(), std::sqrt(0.5));
  EXPECT_EQ(p["min"].get<double>(), 1.0);
  EXPECT_EQ(p["max"].get<double>(), 2.0);
  EXPECT_EQ(p["count"], 2);
  EXPECT_EQ(h["diverged_runs"], 1);
  EXPECT_EQ(h["never_converged_runs"], 0);
  EXPECT_EQ(h["runs_with_failed_steps"], 1);

  // no run has the metric: null, not an object
  for (auto& r : runs) r.filters[0].metrics.converge_time_s.reset();
  const Json k = Json::parse(format_summary_json(scenario(), runs, context()));
  EXPECT_TRUE(k["filters"]["hinf"]["converge_time_s"].is_null());
  EXPECT_EQ(k["filters"]["hinf"]["never_converged_runs"], 2);
}

TEST(SummaryJson, NoRunsAndNoGainsAreEmptyObjects) {
  const Json j = Json::parse(format_summary_json(scenario(), {}, SummaryContext{}));
  EXPECT_EQ(keys(j), kTopKeys);
  EXPECT_TRUE(j["gains"].is_object() && j["gains"].empty());
  EXPECT_TRUE(j["filters"].is_object() && j["filters"].empty());
}

TEST(SummaryJson, RefusesNonFiniteNumbers) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  RunResult run;
  run.filters = {converged("hinf", nan)};
  EXPECT_THROW(format_summary_json(scenario(), {run}, context()), std::logic_error);
  EXPECT_THROW(format_summary_json(scenario(), {run, run}, context()), std::logic_error);
  run.filters = {converged("hinf", 1.0)};
  SummaryContext ctx = context();
  ctx.gains["hinf"].gamma = inf;
  EXPECT_THROW(format_summary_json(scenario(), {run}, ctx), std::logic_error);
  Scenario s = scenario();
  s.truth_delta = nan;
  EXPECT_THROW(format_summary_json(s, {run}, context()), std::logic_error);
  EXPECT_NO_THROW(format_summary_json(scenario(), {run}, context()));
}

}  // namespace
