// The output files of a manoeuvring_target run directory (manoeuvring_report.hpp).
#include "manoeuvring_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "hinf/common/gnuplot.hpp"
#include "hinf/sim/plots.hpp"
#include "summary_json.hpp"

namespace hinf::sim {
namespace {

constexpr const char* kManoeuvringAxes[3] = {"x", "y", "z"};
constexpr const char* kManoeuvringStateNames[6] = {"x", "y", "z", "vx", "vy", "vz"};

// One metric of one filter in one run: under windows.<group> (or at the filter's top level if
// the group is empty), per axis (3 values) or a scalar (1).
struct Metric {
  std::string group, name;
  std::vector<double> value;
  bool count = false;  // a whole number (written as one for a single run)
};

std::vector<double> axes(const Eigen::Vector3d& v) { return {v(0), v(1), v(2)}; }

bool with_paper(const ManoeuvreFilterSettings& f) { return f.covariance != ManoeuvreCovariance::Innovation; }
bool with_innovation(const ManoeuvreFilterSettings& f) { return f.covariance != ManoeuvreCovariance::Paper; }

std::vector<Metric> metric_list(const ManoeuvringExperiment& e, const ManoeuvreFilterSettings& f,
                                const ManoeuvringFilterStatistics& s) {
  std::vector<Metric> m;
  for (std::size_t w = 0; w < e.options.windows.size(); ++w) {
    const std::string& g = e.options.windows[w].name;
    const ManoeuvringWindowStatistics& x = s.windows[w];
    m.push_back({g, "position_rms_m", axes(x.position_rms)});
    m.push_back({g, "velocity_rms_mps", axes(x.velocity_rms)});
    m.push_back({g, "position_error_max_m", axes(x.position_error_max)});
    m.push_back({g, "maneuver_error_mean_mps2", axes(x.u_error_mean)});
    m.push_back({g, "maneuver_error_rms_mps2", axes(x.u_error_rms)});
    m.push_back({g, "maneuver_error_max_mps2", axes(x.u_error_max)});
    if (with_paper(f)) {
      m.push_back({g, "maneuver_sigma_paper_mps2", axes(x.u_sigma_paper)});
      m.push_back({g, "coverage_3sigma_paper", axes(x.coverage_paper)});
    }
    if (with_innovation(f)) {
      m.push_back({g, "maneuver_sigma_innovation_mps2", axes(x.u_sigma_innovation)});
      m.push_back({g, "coverage_3sigma_innovation", axes(x.coverage_innovation)});
    }
    m.push_back({g, "samples", {static_cast<double>(x.samples)}, true});
  }
  m.push_back({"", "settle_after_onset_s", axes(s.settle_after_onset)});
  m.push_back({"", "settle_after_offset_s", axes(s.settle_after_offset)});
  if (f.detector_window > 0) {
    m.push_back({"", "detection_delay_s", {s.detection_delay}});
    m.push_back({"", "false_alarm_rate", {s.false_alarm_rate}});
  }
  m.push_back({"", "final_position_error_m", {s.final_position_error}});
  m.push_back({"", "failed_steps", {static_cast<double>(s.failed_steps)}, true});
  return m;
}

std::string column_name(const Metric& m, std::size_t i) {
  std::string c = m.group.empty() ? m.name : m.group + "_" + m.name;
  if (m.value.size() == 3) c += std::string("_") + kManoeuvringAxes[i];
  return c;
}

Json value_json(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

// One run: the value (null if not finite), per axis an array. Several: {mean, std, min, max,
// count} over the runs with a finite value, per axis each an array.
Json metric_json(const std::vector<std::vector<double>>& per_run, bool count) {
  const std::size_t n = per_run.front().size();
  if (per_run.size() == 1) {
    if (n == 1) return count ? Json(std::llround(per_run.front()[0])) : value_json(per_run.front()[0]);
    Json a = Json::array();
    for (double v : per_run.front()) a.push_back(value_json(v));
    return a;
  }
  std::vector<MetricStats> st;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::optional<double>> v;
    for (const auto& run : per_run)
      if (std::isfinite(run[i])) v.emplace_back(run[i]);
    st.push_back(compute_stats(v));
  }
  Json j = Json::object();
  const auto field = [&](const char* key, auto get) {
    if (n == 1) {
      j[key] = st[0].count ? get(st[0]) : Json(nullptr);
      return;
    }
    Json a = Json::array();
    for (const MetricStats& s : st) a.push_back(s.count ? get(s) : Json(nullptr));
    j[key] = a;
  };
  field("mean", [](const MetricStats& s) { return json_num(s.mean); });
  field("std", [](const MetricStats& s) { return json_num(s.std); });
  field("min", [](const MetricStats& s) { return json_num(s.min); });
  field("max", [](const MetricStats& s) { return json_num(s.max); });
  if (n == 1) j["count"] = st[0].count;
  else {
    Json a = Json::array();
    for (const MetricStats& s : st) a.push_back(s.count);
    j["count"] = a;
  }
  return j;
}

const char* to_string(ManoeuvreCovariance c) {
  return c == ManoeuvreCovariance::Paper ? "paper" : c == ManoeuvreCovariance::Innovation ? "innovation" : "both";
}

Json filter_settings_json(const ManoeuvreFilterSettings& f) {
  Json j = Json::object();
  j["transition"] = models::to_string(f.model.transition);
  j["process_noise_psd"] = json_num(f.model.process_noise_psd);
  j["predict_with_chaser_control"] = f.predict_with_chaser_control;
  j["maneuver_covariance"] = to_string(f.covariance);
  if (f.detector_window > 0) {
    j["detector"] = {{"type", "nis_window"},
                     {"window", f.detector_window},
                     {"p_false_alarm", json_num(f.detector_false_alarm)},
                     {"threshold", json_num(nis_window_threshold(f.detector_window, f.detector_false_alarm))}};
  }
  return j;
}

// The gnuplot script of the three figures of one filter (f: its index; columns of plot.dat:
// t, u_time, then per filter 6 errors, 6 σ, 3 Û errors, 3 σ paper, 3 σ innovation).
void plot_filter(std::ostringstream& gp, const std::string& data, std::size_t f, const std::string& title,
                 const std::vector<std::string>& png) {
  const std::size_t base = 3 + 21 * f;
  const char* what[3] = {"position error (m)", "velocity error (m/s)", "manoeuvre error (m/s^2)"};
  for (int fig = 0; fig < 3; ++fig) {
    const auto ylabel = [&](int c) { return std::string(kManoeuvringAxes[c]) + " " + what[fig]; };
    const auto curves = [&](int c) {
      std::ostringstream plot;
      const std::string t = fig == 2 ? "2" : "1";
      if (fig < 2) {
        const std::size_t e = base + static_cast<std::size_t>(3 * fig + c), s = base + 6 + static_cast<std::size_t>(3 * fig + c);
        plot << gnuplot_quoted(data) << " using " << t << ":" << e << " with lines lw 1 title 'error', "
             << gnuplot_quoted(data) << " using " << t << ":(3*$" << s << ") with lines lc 'gray' title '+3 sigma', "
             << gnuplot_quoted(data) << " using " << t << ":(-3*$" << s << ") with lines lc 'gray' notitle";
      } else {
        const std::size_t e = base + 12 + static_cast<std::size_t>(c), sp = base + 15 + static_cast<std::size_t>(c),
                          si = base + 18 + static_cast<std::size_t>(c);
        plot << gnuplot_quoted(data) << " using 2:" << e << " with lines lw 1 title 'error', "
             << gnuplot_quoted(data) << " using 2:(3*$" << si << ") with lines lc 'gray' title '3 sigma innovation', "
             << gnuplot_quoted(data) << " using 2:(-3*$" << si << ") with lines lc 'gray' notitle, "
             << gnuplot_quoted(data) << " using 2:(3*$" << sp << ") with lines lc 'orange' title '3 sigma (7b)', "
             << gnuplot_quoted(data) << " using 2:(-3*$" << sp << ") with lines lc 'orange' notitle";
      }
      return plot.str();
    };
    gp << gnuplot_stacked_figure(png[static_cast<std::size_t>(fig)], title + ": " + what[fig] + ", run 0", 3, ylabel,
                                 curves);
  }
}

std::string plot_data(const std::vector<std::vector<ManoeuvringSample>>& samples) {
  std::string out;
  const std::size_t steps = samples.empty() ? 0 : samples.front().size();
  for (std::size_t k = 0; k < steps; ++k) {
    append_num(out, samples.front()[k].t);
    out += ' ', append_num(out, samples.front()[k].u_time);
    for (const auto& filter : samples) {
      const ManoeuvringSample& s = filter[k];
      const Eigen::Matrix<double, 6, 1> err = s.estimate - s.truth;
      const Eigen::Vector3d ue = s.u_hat - s.true_u;
      for (int i = 0; i < 6; ++i) out += ' ', append_num(out, err(i));
      for (int i = 0; i < 6; ++i) out += ' ', append_num(out, s.sigma(i));
      for (int i = 0; i < 3; ++i) out += ' ', append_num(out, ue(i));
      for (int i = 0; i < 3; ++i) out += ' ', append_num(out, std::sqrt(s.u_var_paper(i)));
      for (int i = 0; i < 3; ++i) out += ' ', append_num(out, std::sqrt(s.u_var_innovation(i)));
    }
    out += '\n';
  }
  return out;
}

// samples[f] = filter f's samples of run 0.
std::string format_manoeuvring_trajectory_csv(const ManoeuvringExperiment& e,
                                              const std::vector<std::vector<ManoeuvringSample>>& samples) {
  std::string out = "t";
  append_columns(out, "true_", kManoeuvringStateNames);
  out += ",u_time";
  append_columns(out, "true_u", kManoeuvringAxes);
  append_columns(out, "uc_", kManoeuvringAxes);
  append_columns(out, "meas_", kManoeuvringAxes);
  out += ",range";
  for (const auto& f : e.filters) {
    append_columns(out, f.name + "_est_", kManoeuvringStateNames);
    append_columns(out, f.name + "_sigma_", kManoeuvringStateNames);
    append_columns(out, f.name + "_uhat_", kManoeuvringAxes);
    if (with_paper(f))
      append_columns(out, f.name + "_uvar_paper_", kManoeuvringAxes);
    if (with_innovation(f))
      append_columns(out, f.name + "_uvar_innov_", kManoeuvringAxes);
    out += "," + f.name + "_nis," + f.name + "_window_nis," + f.name + "_alarm";
  }
  out += '\n';
  const std::size_t steps = samples.empty() ? 0 : samples.front().size();
  for (std::size_t k = 0; k < steps; ++k) {
    const ManoeuvringSample& s0 = samples.front()[k];
    append_num(out, s0.t);
    append_cells(out, s0.truth, 6);
    out += ',', append_num(out, s0.u_time);
    append_cells(out, s0.true_u, 3);
    append_cells(out, s0.u_chaser, 3);
    append_cells(out, s0.measured_position, 3);
    out += ',', append_num(out, s0.range);
    for (std::size_t f = 0; f < samples.size(); ++f) {
      const ManoeuvringSample& s = samples[f][k];
      append_cells(out, s.estimate, 6);
      append_cells(out, s.sigma, 6);
      append_cells(out, s.u_hat, 3);
      if (with_paper(e.filters[f]))
        append_cells(out, s.u_var_paper, 3);
      if (with_innovation(e.filters[f]))
        append_cells(out, s.u_var_innovation, 3);
      out += ',', append_num(out, s.nis);
      out += ',', append_num(out, s.window_nis);
      out += s.alarm ? ",1" : ",0";
    }
    out += '\n';
  }
  return out;
}

// stats[r][f] = filter f's statistics in run r.
std::string format_manoeuvring_runs_csv(const ManoeuvringExperiment& e,
                                        const std::vector<std::vector<ManoeuvringFilterStatistics>>& stats,
                                        const std::vector<std::uint64_t>& seeds) {
  // Every row has every column (both covariances, the detector's metrics; nan where none).
  const auto all_columns = [](ManoeuvreFilterSettings f) {
    f.covariance = ManoeuvreCovariance::Both;
    f.detector_window = std::max(f.detector_window, 1);
    return f;
  };
  std::string out = "run,seed,filter";
  if (!stats.empty())
    for (const Metric& x : metric_list(e, all_columns(e.filters[0]), stats[0][0]))
      for (std::size_t i = 0; i < x.value.size(); ++i) out += "," + column_name(x, i);
  out += '\n';
  for (std::size_t r = 0; r < stats.size(); ++r)
    for (std::size_t f = 0; f < e.filters.size(); ++f) {
      out += std::to_string(r) + "," + std::to_string(seeds[r]) + "," + e.filters[f].name;
      for (const Metric& x : metric_list(e, all_columns(e.filters[f]), stats[r][f]))
        for (double v : x.value) out += ',', append_num(out, v);
      out += '\n';
    }
  return out;
}

std::string format_manoeuvring_summary_json(const ManoeuvringExperiment& e,
                                            const std::vector<std::vector<ManoeuvringFilterStatistics>>& stats,
                                            const std::string& scenario_path, std::uint64_t seed) {
  Json j = summary_header(scenario_path, seed, stats.size(), e.scenario.duration);
  j["scenario_family"] = "manoeuvring_target";
  j["headline_metrics"] = {"detection_delay_s", "false_alarm_rate", "final_position_error_m"};  // end-of-run table
  j["noise"] = e.scenario.noise;
  Json windows = Json::object();
  for (const MetricWindow& w : e.options.windows) windows[w.name] = {json_num(w.start), json_num(w.end)};
  j["windows_s"] = windows;
  j["maneuver_tolerance_mps2"] = json_num(e.options.maneuver_tolerance);
  Json filters = Json::object();
  for (std::size_t f = 0; f < e.filters.size(); ++f) {
    std::vector<std::vector<Metric>> per_run;
    for (const auto& run : stats) per_run.push_back(metric_list(e, e.filters[f], run[f]));
    Json m = filter_settings_json(e.filters[f]);
    Json win = Json::object();
    for (std::size_t k = 0; k < per_run.front().size(); ++k) {
      std::vector<std::vector<double>> values;
      for (const auto& run : per_run) values.push_back(run[k].value);
      const Metric& x = per_run.front()[k];
      if (x.group.empty()) m[x.name] = metric_json(values, x.count);
      else win[x.group][x.name] = metric_json(values, x.count);
    }
    m["windows"] = win;
    filters[e.filters[f].name] = m;
  }
  j["filters"] = filters;
  return j.dump(2) + "\n";
}

// Per filter F: F_position_error.png, F_velocity_error.png, F_manoeuvre_error.png (run 0),
// into temporaries of `outputs`. Throws PlotError (plots.hpp).
void write_manoeuvring_plots(const std::string& dir, const ManoeuvringExperiment& e,
                             const std::vector<std::vector<ManoeuvringSample>>& samples, const std::string& title,
                             hinf::AtomicFileSet& outputs) {
  namespace fs = std::filesystem;
  hinf::AtomicFileSet scratch;  // never committed: removed on return
  const std::string data = scratch.add((fs::path(dir) / "plot.dat").string(), plot_data(samples));
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,900 enhanced font 'Sans,10'\nset grid\nset lmargin 12\nset rmargin 28\n";
  std::vector<std::string> names, png;
  for (std::size_t f = 0; f < e.filters.size(); ++f) {
    std::vector<std::string> mine;
    for (const char* kind : {"position", "velocity", "manoeuvre"}) {
      const std::string name = e.filters[f].name + "_" + kind + "_error.png";
      names.push_back(name);
      mine.push_back(outputs.reserve((fs::path(dir) / name).string()));
    }
    plot_filter(gp, data, f, title + " (" + e.filters[f].name + ")", mine);
    png.insert(png.end(), mine.begin(), mine.end());
  }
  gp << "set output\n";
  const std::string script = scratch.add((fs::path(dir) / "plot.gp").string(), gp.str());
  run_plot_script(script, png, names);
}

// The Monte-Carlo figure (error_norms.png): the position, velocity and manoeuvre errors' norms
// of every filter, the metric windows' starts marked.
double position_error_m(const ManoeuvringSample& s) { return (s.estimate - s.truth).head<3>().norm(); }
double velocity_error_mps(const ManoeuvringSample& s) { return (s.estimate - s.truth).tail<3>().norm(); }
double manoeuvre_error_mps2(const ManoeuvringSample& s) { return (s.u_hat - s.true_u).norm(); }
families::ErrorBand<ManoeuvringSample> manoeuvring_error_band(const ManoeuvringExperiment& e) {
  families::ErrorBand<ManoeuvringSample> band{{{"|position error| (m)", position_error_m},
                                               {"|velocity error| (m/s)", velocity_error_mps},
                                               {"|manoeuvre error| (m/s^2)", manoeuvre_error_mps2}},
                                              {},
                                              {}};
  for (std::size_t f = 0; f < e.filters.size(); ++f) band.filters.push_back(f);
  for (const MetricWindow& w : e.options.windows) band.marks.emplace_back(w.start, w.name);
  std::ostringstream tolerance;
  tolerance << "settle tolerance " << e.options.maneuver_tolerance << " m/s^2";
  band.thresholds.push_back({2, e.options.maneuver_tolerance, tolerance.str()});
  return band;
}

}  // namespace

namespace families {

const StreamOutputs<ManoeuvringExperiment, ManoeuvringFilterStatistics, ManoeuvringSample>& manoeuvring_outputs() {
  static const StreamOutputs<ManoeuvringExperiment, ManoeuvringFilterStatistics, ManoeuvringSample> outputs{
      format_manoeuvring_trajectory_csv, format_manoeuvring_runs_csv, format_manoeuvring_summary_json,
      write_manoeuvring_plots, manoeuvring_error_band};
  return outputs;
}

}  // namespace families
}  // namespace hinf::sim
