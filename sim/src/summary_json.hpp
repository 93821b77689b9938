// The number formats of hinf-sim's output files, shared by the scenario families:
// CSV cells with 17 significant digits, and summary.json numbers that are never
// non-finite, with {mean, std, min, max, count} over Monte-Carlo runs.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hinf/sim/metrics.hpp"

namespace hinf::sim {

inline void append_num(std::string& out, double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  out += buf;
}

// ",v(0),…,v(n-1)" after a CSV row's first cells (v: any vector indexable by int).
template <class Vector>
void append_cells(std::string& out, const Vector& v, int n) {
  for (int i = 0; i < n; ++i) out += ',', append_num(out, v(i));
}

// ",<prefix><name>" for each of `names`: columns of a CSV header.
template <class Names>
void append_columns(std::string& out, const std::string& prefix, const Names& names) {
  for (const auto& name : names) out += "," + prefix + name;
}

using Json = nlohmann::ordered_json;  // keys in the order written

// summary.json never holds a non-finite number (docs/experiments.md, "Output files").
inline Json json_num(double v) {
  if (!std::isfinite(v)) throw std::logic_error("summary.json: refusing to write a non-finite number");
  return v;
}

inline Json json_opt(const std::optional<double>& v) { return v ? json_num(*v) : Json(nullptr); }

inline Json json_stats(const std::vector<std::optional<double>>& values) {
  const MetricStats s = compute_stats(values);
  if (s.count == 0) return nullptr;
  Json j = Json::object();
  j["mean"] = json_num(s.mean);
  j["std"] = json_num(s.std);
  j["min"] = json_num(s.min);
  j["max"] = json_num(s.max);
  j["count"] = s.count;
  return j;
}

// The median of the finite values (NaN if none).
inline double finite_median(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
}

// {mean, std, min, max, median, p90, count} over the runs with a finite value (a filter
// whose state went non-finite has none); p90 the nearest-rank 90th percentile; null if none.
inline Json stats_json(const std::vector<double>& all) {
  std::vector<double> v;
  for (double x : all)
    if (std::isfinite(x)) v.push_back(x);
  if (v.empty()) return nullptr;
  std::vector<std::optional<double>> o(v.begin(), v.end());
  Json j = json_stats(o);
  Json out = Json::object();
  for (const char* k : {"mean", "std", "min", "max"}) out[k] = j[k];
  out["median"] = json_num(finite_median(v));
  out["p90"] = json_num(nearest_rank_quantile(v, 0.9));
  out["count"] = v.size();
  return out;
}

// One filter's metrics into `m`, per_run[r] = its (name, value) list in run r (the same names in
// every run): the value for one run (null if not finite), stats_json over several.
template <class Name>
void add_metrics_json(Json& m, const std::vector<std::vector<std::pair<Name, double>>>& per_run) {
  for (std::size_t k = 0; k < per_run.front().size(); ++k) {
    std::vector<double> values;
    for (const auto& run : per_run) values.push_back(run[k].second);
    m[per_run.front()[k].first] =
        per_run.size() > 1 ? stats_json(values) : std::isfinite(values.front()) ? Json(values.front()) : Json(nullptr);
  }
}

// metrics(stats[r][f]) for every run r: filter f's (name, value) lists, as add_metrics_json takes them.
template <class Stats, class Metrics>
auto metrics_per_run(const std::vector<std::vector<Stats>>& stats, std::size_t f, const Metrics& metrics) {
  std::vector<decltype(metrics(stats.front()[f]))> per_run;
  for (const auto& run : stats) per_run.push_back(metrics(run[f]));
  return per_run;
}

// runs.csv of a family whose filters each have one (name, value) metric list: "run,seed,filter",
// the metrics' names (from a default Stats), then one row per run and filter.
template <class Filters, class Stats, class Metrics>
std::string metrics_runs_csv(const Filters& filters, const std::vector<std::vector<Stats>>& stats,
                             const std::vector<std::uint64_t>& seeds, const Metrics& metrics) {
  std::string out = "run,seed,filter";
  for (const auto& [name, value] : metrics(Stats())) out += std::string(",") + name;
  out += '\n';
  for (std::size_t r = 0; r < stats.size(); ++r)
    for (std::size_t f = 0; f < filters.size(); ++f) {
      out += std::to_string(r) + "," + std::to_string(seeds[r]) + "," + filters[f].name;
      for (const auto& [name, value] : metrics(stats[r][f])) out += ',', append_num(out, value);
      out += '\n';
    }
  return out;
}

// metrics_runs_csv as a StreamOutputs::runs_csv entry, for a family whose metric list needs
// only the statistics: `metrics_runs_csv_of<&metric_list, Experiment, Stats>`.
template <auto Metrics, class Experiment, class Stats>
std::string metrics_runs_csv_of(const Experiment& e, const std::vector<std::vector<Stats>>& stats,
                                const std::vector<std::uint64_t>& seeds) {
  return metrics_runs_csv(e.filters, stats, seeds, Metrics);
}

// The keys every summary.json starts with.
inline Json summary_header(const std::string& scenario_path, std::uint64_t seed, std::size_t runs, double duration) {
  Json j = Json::object();
  j["format"] = "hinf-sim-summary/1";
  j["scenario"] = scenario_path;
  j["seed"] = seed;
  j["runs"] = runs;
  j["duration_s"] = json_num(duration);
  return j;
}

}  // namespace hinf::sim
