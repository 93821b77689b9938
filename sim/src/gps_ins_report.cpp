// format_gps_ins_* (gps_ins_report.hpp).
#include "hinf/sim/gps_ins_report.hpp"

#include <algorithm>

#include "summary_json.hpp"

namespace hinf::sim {
namespace {

namespace ix = models::gps_ins_index;
constexpr const char* kStateNames[15] = {"x",     "y",     "z",     "vx",     "vy",     "vz",     "sigma1", "sigma2",
                                         "sigma3", "w1",   "w2",    "w3",     "b1",     "b2",     "b3"};
constexpr const char* kErrorNames[15] = {"pos_x", "pos_y", "pos_z", "vel_x", "vel_y", "vel_z", "roll", "pitch",
                                         "yaw",   "rate_1", "rate_2", "rate_3", "bias_1", "bias_2", "bias_3"};

// The metrics of one filter in one run, in the order of runs.csv and summary.json (largest
// component of each block).
std::vector<std::pair<const char*, double>> metric_list(const GpsInsFilterStatistics& s) {
  return {{"position_max_m", s.position_max.maxCoeff()},     {"velocity_max_mps", s.velocity_max.maxCoeff()},
          {"attitude_max_deg", s.attitude_max.maxCoeff()},   {"rate_max_dps", s.rate_max.maxCoeff()},
          {"bias_max_dps", s.bias_max.maxCoeff()},           {"position_rms_m", s.position_rms.maxCoeff()},
          {"velocity_rms_mps", s.velocity_rms.maxCoeff()},   {"attitude_rms_deg", s.attitude_rms.maxCoeff()},
          {"rate_rms_dps", s.rate_rms.maxCoeff()},           {"bias_rms_dps", s.bias_rms.maxCoeff()},
          {"nees_mean", s.nees_mean},                        {"gamma_violations", static_cast<double>(s.gamma_violations)},
          {"failed_steps", static_cast<double>(s.failed_steps)}, {"diverged", s.diverged ? 1.0 : 0.0}};
}

// {mean, std, min, max, median, p90, count} over the runs with a finite value (a filter
// whose state went non-finite has none); p90 the nearest-rank 90th percentile; null if none.
Json stats_json(const std::vector<double>& all) {
  std::vector<double> v;
  for (double x : all)
    if (std::isfinite(x)) v.push_back(x);
  if (v.empty()) return nullptr;
  std::vector<std::optional<double>> o(v.begin(), v.end());
  Json j = json_stats(o);
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  Json out = Json::object();
  for (const char* k : {"mean", "std", "min", "max"}) out[k] = j[k];
  out["median"] = json_num(0.5 * (v[(n - 1) / 2] + v[n / 2]));
  out["p90"] = json_num(v[std::min(n - 1, static_cast<std::size_t>(std::ceil(0.9 * n)) - 1)]);
  out["count"] = n;
  return out;
}

}  // namespace

std::string format_gps_ins_trajectory_csv(const GpsInsExperiment& e,
                                          const std::vector<std::vector<GpsInsSample>>& samples) {
  std::string out = "t";
  for (const char* n : kStateNames) out += std::string(",truth_") + n;
  for (const auto& f : e.filters) {
    for (const char* n : kStateNames) out += "," + f.name + "_" + n;
    for (const char* n : kErrorNames) out += "," + f.name + "_err_" + n;
    for (const char* n : kErrorNames) out += "," + f.name + "_3sigma_" + n;
    out += "," + f.name + "_nees";
  }
  out += '\n';
  const std::size_t steps = samples.empty() ? 0 : samples.front().size();
  for (std::size_t k = 0; k < steps; ++k) {
    append_num(out, samples.front()[k].t);
    for (int i = 0; i < 15; ++i) out += ',', append_num(out, samples.front()[k].truth(i));
    for (const auto& filter : samples) {
      const GpsInsSample& s = filter[k];
      const auto err = error_in_report_units(s), sig = sigma_in_report_units(s);
      for (int i = 0; i < 15; ++i) out += ',', append_num(out, s.estimate(i));
      for (int i = 0; i < 15; ++i) out += ',', append_num(out, err(i));
      for (int i = 0; i < 15; ++i) out += ',', append_num(out, 3 * sig(i));
      out += ',', append_num(out, s.nees);
    }
    out += '\n';
  }
  return out;
}

std::string format_gps_ins_runs_csv(const GpsInsExperiment& e,
                                    const std::vector<std::vector<GpsInsFilterStatistics>>& stats,
                                    const std::vector<std::uint64_t>& seeds) {
  std::string out = "run,seed,filter";
  for (const auto& [name, value] : metric_list(GpsInsFilterStatistics())) out += std::string(",") + name;
  out += '\n';
  for (std::size_t r = 0; r < stats.size(); ++r)
    for (std::size_t f = 0; f < e.filters.size(); ++f) {
      out += std::to_string(r) + "," + std::to_string(seeds[r]) + "," + e.filters[f].name;
      for (const auto& [name, value] : metric_list(stats[r][f])) out += ',', append_num(out, value);
      out += '\n';
    }
  return out;
}

std::string format_gps_ins_summary_json(const GpsInsExperiment& e,
                                        const std::vector<std::vector<GpsInsFilterStatistics>>& stats,
                                        const std::string& scenario_path, std::uint64_t seed) {
  Json j = summary_header(scenario_path, seed, stats.size(), e.scenario.duration);
  j["scenario_family"] = "gps_ins_relative";
  j["steady_state_window_s"] = Json::array({json_num(e.options.window_start), json_num(e.options.window_end)});
  j["inertia_products_fraction"] = json_num(e.scenario.inertia_products_fraction);
  Json filters = Json::object();
  for (std::size_t f = 0; f < e.filters.size(); ++f) {
    std::vector<std::vector<std::pair<const char*, double>>> per_run;  // [run][metric]
    for (const auto& run : stats) per_run.push_back(metric_list(run[f]));
    Json m = Json::object();
    for (std::size_t k = 0; k < per_run.front().size(); ++k) {
      std::vector<double> values;
      for (const auto& run : per_run) values.push_back(run[k].second);
      m[per_run.front()[k].first] =
          stats.size() > 1 ? stats_json(values) : std::isfinite(values.front()) ? Json(values.front()) : Json(nullptr);
    }
    filters[e.filters[f].name] = m;
  }
  j["filters"] = filters;
  return j.dump(2) + "\n";
}

}  // namespace hinf::sim
