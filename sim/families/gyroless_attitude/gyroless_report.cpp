// The output files of a gyroless_attitude run directory (gyroless_report.hpp).
#include "gyroless_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "hinf/common/gnuplot.hpp"
#include "hinf/sim/plots.hpp"
#include "summary_json.hpp"

namespace hinf::sim {
namespace {

namespace rb = models::rigid_body_index;
constexpr double kDegreesPerRadian = 1 / models::kRadiansPerDegree;
constexpr const char* kTruthNames[13] = {"q1", "q2", "q3", "q4", "wx", "wy", "wz",
                                         "tx", "ty", "tz", "dtx", "dty", "dtz"};
constexpr const char* kGyrolessErrorNames[9] = {"roll", "pitch", "yaw", "wx", "wy", "wz", "tx", "ty", "tz"};
constexpr const char* kGyrolessAxes[3] = {"x", "y", "z"};

// The metrics of one filter in one run, in the order of runs.csv and summary.json.
std::vector<std::pair<std::string, double>> gyroless_metric_list(const GyrolessFilterStatistics& s) {
  std::vector<std::pair<std::string, double>> m{{"attitude_rms_deg", s.attitude_rms_norm_deg}};
  for (int i = 0; i < 3; ++i) m.emplace_back(std::string("attitude_rms_deg_") + kGyrolessErrorNames[i], s.attitude_rms_deg(i));
  m.emplace_back("torque_rms_nm", s.torque_rms_norm);
  for (int i = 0; i < 3; ++i) m.emplace_back(std::string("torque_rms_nm_") + kGyrolessAxes[i], s.torque_rms(i));
  m.emplace_back("torque_p95_nm", s.torque_p95);
  m.emplace_back("attitude_max_deg", s.attitude_max_deg);
  m.emplace_back("nees_mean", s.nees_mean);
  m.emplace_back("torque_rate_correlation", s.torque_rate_correlation_norm);
  for (int i = 0; i < 3; ++i)
    m.emplace_back(std::string("torque_rate_correlation_") + kGyrolessAxes[i], s.torque_rate_correlation(i));
  m.emplace_back("lambda_cap_hits", static_cast<double>(s.lambda_cap_hits));
  m.emplace_back("lambda_cap_fraction", s.steps ? static_cast<double>(s.lambda_cap_hits) / s.steps : 0.0);
  m.emplace_back("failed_steps", static_cast<double>(s.failed_steps));
  m.emplace_back("stopped", s.stopped ? 1.0 : 0.0);
  return m;
}

// The sample's error and 1σ in report units: deg for the attitude, rad/s, N m.
Eigen::Matrix<double, 9, 1> in_report_units(const Eigen::Matrix<double, 9, 1>& v) {
  Eigen::Matrix<double, 9, 1> r = v;
  r.segment<3>(rb::kAttitudeError) *= kDegreesPerRadian;
  return r;
}

// A figure: file, title, the filters drawn (indices), the error block (attitude or torque).
struct Figure {
  std::string file, title;
  std::vector<std::size_t> filters;
  int block;  // rb::kAttitudeError or rb::kTorqueError; -1 for the true torque
};

std::vector<Figure> figures(const GyrolessExperiment& e) {
  std::vector<std::size_t> aekf_sweep, astekf_sweep, aaekf, named;
  for (std::size_t f = 0; f < e.filters.size(); ++f) {
    const GyrolessFilterSettings& s = e.filters[f];
    if (s.swept_from.empty()) named.push_back(f);
    if (s.kind == GyrolessFilterKind::Aaekf) aaekf.push_back(f);
    if (!s.swept_from.empty() && s.kind == GyrolessFilterKind::Aekf) aekf_sweep.push_back(f);
    if (!s.swept_from.empty() && s.kind == GyrolessFilterKind::Astekf) astekf_sweep.push_back(f);
  }
  // the noisiest (largest Q) drawn first, so that the lag of the small Qs shows on top of it
  const auto by_Q_descending = [&](std::size_t a, std::size_t b) { return e.filters[a].Q > e.filters[b].Q; };
  std::stable_sort(aekf_sweep.begin(), aekf_sweep.end(), by_Q_descending);
  std::stable_sort(astekf_sweep.begin(), astekf_sweep.end(), by_Q_descending);
  std::vector<Figure> out{{"fig1_torque.png", "disturbance torque (truth)", {}, -1}};
  const auto pair = [&](int n, const char* who, const std::vector<std::size_t>& f) {
    if (f.empty()) return;
    out.push_back({"fig" + std::to_string(n) + "_" + who + "_torque_error.png", std::string(who) + ": torque error", f,
                   rb::kTorqueError});
    out.push_back({"fig" + std::to_string(n + 1) + "_" + who + "_attitude_error.png",
                   std::string(who) + ": attitude error (2 dq_v)", f, rb::kAttitudeError});
  };
  pair(2, "aekf_sweep", aekf_sweep);
  pair(4, "astekf_sweep", astekf_sweep);
  pair(6, "aaekf", aaekf);
  pair(8, "comparison", named);
  return out;
}

// plot.dat: t, the true torque, then per filter its 9 errors in report units.
std::string plot_data(const std::vector<std::vector<GyrolessSample>>& samples) {
  std::string out;
  const std::size_t steps = samples.empty() ? 0 : samples.front().size();
  for (std::size_t k = 0; k < steps; ++k) {
    append_num(out, samples.front()[k].t);
    for (int i = 0; i < 3; ++i) out += ' ', append_num(out, samples.front()[k].truth(rb::kTorque + i));
    for (const auto& filter : samples) {
      const auto err = in_report_units(filter[k].error);
      for (int i = 0; i < 9; ++i) out += ' ', append_num(out, err(i));
    }
    out += '\n';
  }
  return out;
}

std::string plot_script(const GyrolessExperiment& e, const std::vector<Figure>& figs, const std::string& title,
                        const std::string& data, const std::vector<std::string>& png) {
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,900 enhanced font 'Sans,10'\nset grid\nset lmargin 12\nset rmargin 24\n";
  for (std::size_t i = 0; i < figs.size(); ++i) {
    const Figure& F = figs[i];
    const bool torque = F.block != rb::kAttitudeError;
    const auto ylabel = [&](int c) {
      return torque ? std::string("T_") + kGyrolessAxes[c] + " (N m)" : std::string(kGyrolessErrorNames[c]) + " (deg)";
    };
    const auto curves = [&](int c) {
      std::ostringstream plot;
      if (F.block < 0) {
        plot << gnuplot_quoted(data) << " using 1:" << 2 + c << " with lines lw 1.5 title 'truth'";
        return plot.str();
      }
      for (std::size_t n = 0; n < F.filters.size(); ++n) {  // solid first, then dashed, dotted: the
        const std::size_t i = n, f = F.filters[n];          // later curves let the earlier show through
        const std::size_t col = 5 + 9 * f + static_cast<std::size_t>(F.block + c);
        plot << (i ? ", " : "") << gnuplot_quoted(data) << " using 1:" << col << " with lines lw 1.2 dt " << 1 + n % 5
             << " lc " << n + 1 << " title " << gnuplot_quoted(e.filters[f].name) << " noenhanced";
      }
      return plot.str();
    };
    gp << gnuplot_stacked_figure(png[i], title + ": " + F.title + ", run 0", 3, ylabel, curves);
  }
  gp << "set output\n";
  return gp.str();
}

// samples[f] = filter f's samples of run 0.
std::string format_gyroless_trajectory_csv(const GyrolessExperiment& e,
                                           const std::vector<std::vector<GyrolessSample>>& samples) {
  std::string out = "t";
  append_columns(out, "truth_", kTruthNames);
  for (const auto& f : e.filters) {
    append_columns(out, f.name + "_err_", kGyrolessErrorNames);
    append_columns(out, f.name + "_sig_", kGyrolessErrorNames);
    append_columns(out, f.name + "_Q_", kGyrolessAxes);
    out += "," + f.name + "_lambda_att," + f.name + "_lambda_rate," + f.name + "_lambda_torque," + f.name + "_nees";
  }
  out += '\n';
  const std::size_t steps = samples.empty() ? 0 : samples.front().size();
  for (std::size_t k = 0; k < steps; ++k) {
    const GyrolessSample& s0 = samples.front()[k];
    append_num(out, s0.t);
    append_cells(out, s0.truth, 10);
    append_cells(out, s0.torque_rate, 3);
    for (const auto& filter : samples) {
      const GyrolessSample& s = filter[k];
      const auto err = in_report_units(s.error), sig = in_report_units(s.sigma);
      append_cells(out, err, 9);
      append_cells(out, sig, 9);
      append_cells(out, s.q_torque, 3);
      for (int b = 0; b < 3; ++b) out += ',', append_num(out, s.lambda.segment<3>(3 * b).maxCoeff());
      out += ',', append_num(out, s.nees);
    }
    out += '\n';
  }
  return out;
}

std::string format_gyroless_summary_json(const GyrolessExperiment& e,
                                         const std::vector<std::vector<GyrolessFilterStatistics>>& stats,
                                         const std::string& scenario_path, std::uint64_t seed) {
  Json j = summary_header(scenario_path, seed, stats.size(), e.scenario.duration);
  j["scenario_family"] = "gyroless_attitude";
  j["headline_metrics"] = {"attitude_rms_deg", "torque_rms_nm", "nees_mean"};  // hinf-sim's end-of-run table
  j["steady_state_start_s"] = json_num(e.options.window_start);
  Json filters = Json::object();
  for (std::size_t f = 0; f < e.filters.size(); ++f) {
    const auto per_run = metrics_per_run(stats, f, gyroless_metric_list);
    Json m = Json::object();
    m["type"] = e.filters[f].kind == GyrolessFilterKind::Aekf     ? "aekf"
                : e.filters[f].kind == GyrolessFilterKind::Astekf ? "astekf"
                                                                  : "aaekf";
    if (e.filters[f].kind != GyrolessFilterKind::Aaekf) m["Q"] = json_num(e.filters[f].Q);
    add_metrics_json(m, per_run);
    filters[e.filters[f].name] = m;
  }
  j["filters"] = filters;
  return j.dump(2) + "\n";
}

// The source's Figs. 1–9 for run 0 into temporaries of `outputs`: fig1_torque.png (the true
// torque), fig2/fig3 the torque and attitude errors of the AEKF sweep, fig4/fig5 of the
// ASTEKF sweep, fig6/fig7 of the AAEKFs, fig8/fig9 the comparison of the named filters.
// Throws PlotError (plots.hpp).
void write_gyroless_plots(const std::string& dir, const GyrolessExperiment& e,
                          const std::vector<std::vector<GyrolessSample>>& samples, const std::string& title,
                          hinf::AtomicFileSet& outputs) {
  namespace fs = std::filesystem;
  const std::vector<Figure> figs = figures(e);
  std::vector<std::string> names, png;
  for (const Figure& F : figs) {
    names.push_back(F.file);
    png.push_back(outputs.reserve((fs::path(dir) / F.file).string()));
  }
  hinf::AtomicFileSet scratch;  // never committed: removed on return
  const std::string data = scratch.add((fs::path(dir) / "plot.dat").string(), plot_data(samples));
  const std::string script = scratch.add((fs::path(dir) / "plot.gp").string(), plot_script(e, figs, title, data, png));
  run_plot_script(script, png, names);
}

// The Monte-Carlo figure (error_norms.png): |attitude error| and |torque error| of the named
// filters (not the sweeps' entries), the steady-state window's start marked.
double attitude_error_deg(const GyrolessSample& s) { return in_report_units(s.error).segment<3>(rb::kAttitudeError).norm(); }
double torque_error_nm(const GyrolessSample& s) { return s.error.segment<3>(rb::kTorqueError).norm(); }
families::ErrorBand<GyrolessSample> gyroless_error_band(const GyrolessExperiment& e) {
  families::ErrorBand<GyrolessSample> band{
      {{"|attitude error| (deg)", attitude_error_deg}, {"|torque error| (N m)", torque_error_nm}},
      {},
      {{e.options.window_start, "steady state"}}};
  for (std::size_t f = 0; f < e.filters.size(); ++f)
    if (e.filters[f].swept_from.empty()) band.filters.push_back(f);
  return band;
}

}  // namespace

namespace families {

const StreamOutputs<GyrolessExperiment, GyrolessFilterStatistics, GyrolessSample>& gyroless_outputs() {
  static const StreamOutputs<GyrolessExperiment, GyrolessFilterStatistics, GyrolessSample> outputs{
      format_gyroless_trajectory_csv,
      metrics_runs_csv_of<&gyroless_metric_list, GyrolessExperiment, GyrolessFilterStatistics>,
      format_gyroless_summary_json, write_gyroless_plots, gyroless_error_band};
  return outputs;
}

}  // namespace families
}  // namespace hinf::sim
