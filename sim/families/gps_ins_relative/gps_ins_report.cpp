// The output files of a gps_ins_relative run directory (gps_ins_report.hpp).
#include "gps_ins_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "hinf/common/gnuplot.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/sim/plots.hpp"
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
std::vector<std::pair<const char*, double>> gps_ins_metric_list(const GpsInsFilterStatistics& s) {
  return {{"position_max_m", s.position_max.maxCoeff()},     {"velocity_max_mps", s.velocity_max.maxCoeff()},
          {"attitude_max_deg", s.attitude_max.maxCoeff()},   {"rate_max_dps", s.rate_max.maxCoeff()},
          {"bias_max_dps", s.bias_max.maxCoeff()},           {"position_rms_m", s.position_rms.maxCoeff()},
          {"velocity_rms_mps", s.velocity_rms.maxCoeff()},   {"attitude_rms_deg", s.attitude_rms.maxCoeff()},
          {"rate_rms_dps", s.rate_rms.maxCoeff()},           {"bias_rms_dps", s.bias_rms.maxCoeff()},
          {"nees_mean", s.nees_mean},                        {"gamma_violations", static_cast<double>(s.gamma_violations)},
          {"failed_steps", static_cast<double>(s.failed_steps)}, {"diverged", s.diverged ? 1.0 : 0.0}};
}

// The figures of write_gps_ins_plots: file, quantity, first error index, unit.
struct GpsInsFigure {
  const char* file;
  const char* quantity;
  int first;
  const char* unit;
};
constexpr GpsInsFigure kFigures[4] = {{"fig1_position.png", "relative position error", ix::kPosition, "m"},
                                      {"fig2_velocity.png", "relative velocity error", ix::kVelocity, "m/s"},
                                      {"fig3_attitude.png", "attitude error (3-1-2)", ix::kAttitude, "deg"},
                                      {"fig4_rate.png", "angular-rate error", ix::kRate, "deg/s"}};

// plot.dat: t, then per filter the 12 errors of the four figures and their 3σ, over the window.
std::string plot_data(const GpsInsExperiment& e, const std::vector<std::vector<GpsInsSample>>& samples) {
  std::string out;
  const std::size_t steps = samples.empty() ? 0 : samples.front().size();
  for (std::size_t k = 0; k < steps; ++k) {
    const double t = samples.front()[k].t;
    if (t < e.options.window_start || t > e.options.window_end) continue;
    append_num(out, t);
    for (const auto& filter : samples) {
      const auto err = error_in_report_units(filter[k]), sig = sigma_in_report_units(filter[k]);
      for (int i = 0; i < 12; ++i) out += ' ', append_num(out, err(i));
      for (int i = 0; i < 12; ++i) out += ' ', append_num(out, 3 * sig(i));
    }
    out += '\n';
  }
  return out;
}

// One png per figure, three panels (the components), each filter's error (its own dash type:
// solid, dashed, dotted, …) and ±3σ (thin, dashed) in one colour.
std::string plot_script(const GpsInsExperiment& e, const std::string& title, const std::string& data,
                        const std::vector<std::string>& png) {
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,900 enhanced font 'Sans,10'\nset grid\nset key outside right top\nset lmargin 12\nset rmargin 24\n";
  for (int fig = 0; fig < 4; ++fig) {
    const GpsInsFigure& F = kFigures[fig];
    const auto ylabel = [&](int c) { return std::string(kErrorNames[F.first + c]) + " (" + F.unit + ")"; };
    const auto curves = [&](int c) {
      std::ostringstream plot;
      for (std::size_t f = 0; f < e.filters.size(); ++f) {  // solid first, then dashed, dotted: the
        const std::size_t i = f;                             // later curves let the earlier show through
        const std::size_t err_col = 2 + 24 * f + static_cast<std::size_t>(F.first + c), sig_col = err_col + 12;
        const std::string lc = " lc " + std::to_string(f + 1);
        plot << (i ? ", " : "") << gnuplot_quoted(data) << " using 1:" << err_col << " with lines lw 1.2 dt " << 1 + f
             << lc << " title " << gnuplot_quoted(e.filters[f].name) << " noenhanced, '' using 1:" << sig_col
             << " with lines lw 0.7 dt 2" << lc << " title " << gnuplot_quoted(e.filters[f].name + " ±3σ")
             << " noenhanced, '' using 1:(-$" << sig_col << ") with lines lw 0.7 dt 2" << lc << " notitle";
      }
      return plot.str();
    };
    gp << gnuplot_stacked_figure(png[static_cast<std::size_t>(fig)],
                                 title + ": " + F.quantity + ", run 0, steady-state window", 3, ylabel, curves);
  }
  gp << "set output\n";
  return gp.str();
}

// samples[f] = filter f's samples of run 0.
std::string format_gps_ins_trajectory_csv(const GpsInsExperiment& e,
                                          const std::vector<std::vector<GpsInsSample>>& samples) {
  std::string out = "t";
  append_columns(out, "truth_", kStateNames);
  for (const auto& f : e.filters) {
    append_columns(out, f.name + "_", kStateNames);
    append_columns(out, f.name + "_err_", kErrorNames);
    append_columns(out, f.name + "_3sigma_", kErrorNames);
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
      append_cells(out, s.estimate, 15);
      append_cells(out, err, 15);
      append_cells(out, 3 * sig, 15);
      out += ',', append_num(out, s.nees);
    }
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
    const auto per_run = metrics_per_run(stats, f, gps_ins_metric_list);
    Json m = Json::object();
    add_metrics_json(m, per_run);
    filters[e.filters[f].name] = m;
  }
  j["filters"] = filters;
  return j.dump(2) + "\n";
}

// Draws the source's Figs. 1–4 for run 0 over the steady-state window — DIR/fig1_position.png,
// fig2_velocity.png, fig3_attitude.png, fig4_rate.png: each component's error and ±3σ per
// filter — into temporaries of `outputs`. Throws PlotError (plots.hpp).
void write_gps_ins_plots(const std::string& dir, const GpsInsExperiment& e,
                         const std::vector<std::vector<GpsInsSample>>& samples, const std::string& title,
                         hinf::AtomicFileSet& outputs) {
  namespace fs = std::filesystem;
  std::vector<std::string> names, png;
  for (const GpsInsFigure& F : kFigures) {
    names.emplace_back(F.file);
    png.push_back(outputs.reserve((fs::path(dir) / F.file).string()));
  }
  hinf::AtomicFileSet scratch;  // never committed: removed on return
  const std::string data = scratch.add((fs::path(dir) / "plot.dat").string(), plot_data(e, samples));
  const std::string script = scratch.add((fs::path(dir) / "plot.gp").string(), plot_script(e, title, data, png));
  run_plot_script(script, png, names);
}

}  // namespace

// campaigns[i][r][f] = filter f's statistics in run r of the campaign whose truth has the
// products-of-inertia fraction fractions[i]. One row per fraction and filter: the median over
// the runs of each axis's window maximum (attitude as 3-1-2 roll, pitch, yaw in deg; rate and
// bias in deg/s), the layout of the source's Table 1, and the median of the runs' mean NEES.
std::string format_gps_ins_table1_csv(const GpsInsExperiment& e, const std::vector<double>& fractions,
                                      const std::vector<std::vector<std::vector<GpsInsFilterStatistics>>>& campaigns) {
  std::string out =
      "inertia_products_fraction,filter,runs,attitude_roll_deg,attitude_pitch_deg,attitude_yaw_deg,"
      "rate_1_dps,rate_2_dps,rate_3_dps,bias_1_dps,bias_2_dps,bias_3_dps,nees_mean\n";
  for (std::size_t i = 0; i < fractions.size(); ++i)
    for (std::size_t f = 0; f < e.filters.size(); ++f) {
      out += number_text(fractions[i]) + "," + e.filters[f].name + "," + std::to_string(campaigns[i].size());
      for (const Eigen::Vector3d GpsInsFilterStatistics::*block :
           {&GpsInsFilterStatistics::attitude_max, &GpsInsFilterStatistics::rate_max, &GpsInsFilterStatistics::bias_max})
        for (int axis = 0; axis < 3; ++axis) {
          std::vector<double> v;
          for (const auto& run : campaigns[i]) v.push_back((run[f].*block)(axis));
          out += ',';
          const double m = finite_median(v);
          if (std::isfinite(m)) append_num(out, m);
        }
      std::vector<double> nees;
      for (const auto& run : campaigns[i]) nees.push_back(run[f].nees_mean);
      out += ',';
      if (const double m = finite_median(nees); std::isfinite(m)) append_num(out, m);
      out += '\n';
    }
  return out;
}

namespace {

// The Monte-Carlo figure (error_norms.png): the norms of the four figures' errors in report
// units, every filter, the steady-state window marked.
template <int First>
double error_norm_of(const GpsInsSample& s) { return error_in_report_units(s).segment<3>(First).norm(); }
families::ErrorBand<GpsInsSample> gps_ins_error_band(const GpsInsExperiment& e) {
  families::ErrorBand<GpsInsSample> band{{{"|position error| (m)", error_norm_of<ix::kPosition>},
                                          {"|velocity error| (m/s)", error_norm_of<ix::kVelocity>},
                                          {"|attitude error| (deg)", error_norm_of<ix::kAttitude>},
                                          {"|rate error| (deg/s)", error_norm_of<ix::kRate>}},
                                         {},
                                         {{e.options.window_start, "window"}}};
  if (e.options.window_end < e.scenario.duration) band.marks.emplace_back(e.options.window_end, "window end");
  for (std::size_t f = 0; f < e.filters.size(); ++f) band.filters.push_back(f);
  return band;
}

}  // namespace

namespace families {

const StreamOutputs<GpsInsExperiment, GpsInsFilterStatistics, GpsInsSample>& gps_ins_outputs() {
  static const StreamOutputs<GpsInsExperiment, GpsInsFilterStatistics, GpsInsSample> outputs{
      format_gps_ins_trajectory_csv,
      metrics_runs_csv_of<&gps_ins_metric_list, GpsInsExperiment, GpsInsFilterStatistics>,
      format_gps_ins_summary_json, write_gps_ins_plots, gps_ins_error_band};
  return outputs;
}

}  // namespace families
}  // namespace hinf::sim
