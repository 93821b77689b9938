// format_hold_* and write_hold_plots (hold_report.hpp).
#include "hinf/sim/hold_report.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "hinf/common/gnuplot.hpp"
#include "hinf/sim/plots.hpp"
#include "summary_json.hpp"

namespace hinf::sim {
namespace {

// The metrics of one run in the order of runs.csv and summary.json.
std::vector<std::pair<const char*, std::optional<double>>> metric_list(const HoldMetrics& m) {
  return {{"position_rms_m", m.position_rms_m},
          {"position_max_m", m.position_max_m},
          {"velocity_rms_mps", m.velocity_rms_mps},
          {"settle_time_s", m.settle_time_s},
          {"delta_v_mps", m.delta_v_mps},
          {"pulse_count", static_cast<double>(m.pulse_count)},
          {"min_pulse_s", m.min_pulse_s},
          {"saturation_fraction", m.saturation_fraction}};
}

}  // namespace

std::string format_hold_trajectory_csv(const HoldTrajectory& tr) {
  std::string out = "t,err_x,err_y,err_z,vel_x,vel_y,vel_z,cmd_x,cmd_y,cmd_z,force_x,force_y,force_z,pulse_x,pulse_y,pulse_z\n";
  out.reserve(tr.t.size() * 16 * 24);
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    append_num(out, tr.t[k]);
    append_cells(out, tr.error[k], 3);
    append_cells(out, tr.velocity[k], 3);
    append_cells(out, tr.command[k], 3);
    append_cells(out, tr.force[k], 3);
    for (int i = 0; i < 3; ++i) out += ',' + std::to_string(tr.pulse[k](i));
    out += '\n';
  }
  return out;
}

std::string format_hold_runs_csv(const std::vector<HoldRunResult>& runs) {
  std::string out = "run,seed";
  for (const auto& [name, value] : metric_list(HoldMetrics())) out += std::string(",") + name;
  out += '\n';
  for (std::size_t r = 0; r < runs.size(); ++r) {
    out += std::to_string(r) + "," + std::to_string(runs[r].seed);
    for (const auto& [name, value] : metric_list(runs[r].metrics)) {
      out += ',';
      if (value) append_num(out, *value);
    }
    out += '\n';
  }
  return out;
}

std::string format_hold_summary_json(const HoldScenario& s, const std::vector<HoldRunResult>& runs,
                                     const HoldSummaryContext& ctx) {
  Json j = summary_header(ctx.scenario_path, ctx.seed, runs.size(), s.duration);
  j["family"] = "tumbling_hold";
  j["control_sample_time_s"] = json_num(s.control_sample_time);
  j["integration_step_s"] = json_num(s.integration_step);
  j["modulator"] = to_string(s.modulator);
  j["steady_state_start_s"] = json_num(s.steady_state_start);
  j["settle_threshold_m"] = json_num(s.settle_threshold);
  Json& c = j["controller"] = Json::object();
  c["origin"] = ctx.controller_origin;
  c["gamma"] = json_opt(ctx.gamma);
  c["feedforward_N"] = {json_num(ctx.feedforward(0)), json_num(ctx.feedforward(1)), json_num(ctx.feedforward(2))};
  Json& m = j["metrics"] = Json::object();
  const auto names = metric_list(HoldMetrics());
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::vector<std::optional<double>> values;
    for (const auto& run : runs) values.push_back(metric_list(run.metrics)[i].second);
    m[names[i].first] = runs.size() == 1 ? json_opt(values.front()) : json_stats(values);
  }
  if (runs.size() > 1) {
    long never = 0;
    for (const auto& run : runs) never += run.metrics.settle_time_s ? 0 : 1;
    j["never_settled_runs"] = never;
  }
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

// The thrusters' figure plots each axis's applied force as its moving mean over 1 % of the run
// (a pulse train's duty cycle, signed, in N) beside the command U, one strip per axis.
constexpr double kThrustMeanFraction = 0.01;

void write_hold_plots(const std::string& dir, const HoldTrajectory& tr, const std::string& title,
                      hinf::AtomicFileSet& outputs) {
  namespace fs = std::filesystem;
  const std::vector<std::string> names = {"position.png", "velocity.png", "thrusters.png"};
  std::vector<std::string> png;
  for (const auto& n : names) png.push_back(outputs.reserve((fs::path(dir) / n).string()));
  const std::size_t window = std::max<std::size_t>(1, static_cast<std::size_t>(kThrustMeanFraction * tr.t.size()));
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::ostringstream data;  // t, error (3), velocity (3), force (3), its moving mean (3), command (3)
  data.precision(9);
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    sum += tr.force[k];
    if (k >= window) sum -= tr.force[k - window];
    const Eigen::Vector3d mean = sum / static_cast<double>(std::min(k + 1, window));
    data << tr.t[k];
    for (const auto* v : {&tr.error[k], &tr.velocity[k], &tr.force[k], &mean, &tr.command[k]})
      for (int i = 0; i < 3; ++i) data << ' ' << (*v)(i);
    data << '\n';
  }
  hinf::AtomicFileSet scratch;  // never committed: removed on return
  const std::string dat = scratch.add((fs::path(dir) / "plot.dat").string(), data.str());
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,560 enhanced font 'Sans,11'\nset grid\nset key outside right top\n"
     << "set xlabel 'time (s)'\nset datafile missing 'nan'\n";
  const char* what[] = {"position error ρ − ρ* (m)", "velocity ρ̇ (m/s)"};
  for (int f = 0; f < 2; ++f) {
    gp << "set output " << gnuplot_quoted(png[f]) << "\nset ylabel " << gnuplot_quoted(what[f])
       << "\nset title " << gnuplot_quoted(title + ": " + what[f] + ", run 0") << " noenhanced\nplot ";
    for (int i = 0; i < 3; ++i)
      gp << (i ? ", " : "") << gnuplot_quoted(dat) << " using 1:" << 2 + 3 * f + i << " with lines lw 1.2 title "
         << gnuplot_quoted(std::string(1, "xyz"[i]));
    gp << "\n";
  }
  std::ostringstream heading;
  heading.precision(3);
  heading << title << ": thrust per axis, run 0: moving mean over " << window * (tr.t.size() > 1 ? tr.t[1] - tr.t[0] : 0)
          << " s (the pulses' duty cycle) and the command U";
  gp << "unset title\nunset xlabel\n"
     << gnuplot_stacked_figure(
            png[2], heading.str(), 3, [](int p) { return std::string("F_") + "xyz"[p] + " (N)"; },
            [&](int p) {
              return gnuplot_quoted(dat) + " using 1:" + std::to_string(11 + p) +
                     " with lines lw 1.8 lc rgb '#1f77b4' title 'moving mean', '' using 1:" + std::to_string(14 + p) +
                     " with lines lw 0.8 dt 2 lc rgb '#d62728' title 'command U'";
            })
     << "set output\n";
  const std::string script = scratch.add((fs::path(dir) / "plot.gp").string(), gp.str());
  run_plot_script(script, png, names);
}

void write_hold_error_band(const std::string& dir, const std::vector<HoldRunResult>& runs, const HoldScenario& s,
                           const std::string& title, hinf::AtomicFileSet& outputs) {
  std::ostringstream settle;
  settle << "settle " << s.settle_threshold << " m";
  const ErrorBandFigure fig{"error_norms.png",
                            title,
                            {"closed loop"},
                            {"|ρ − ρ*| (m)", "|ρ̇| (m/s)"},
                            hold_trace_window(s),
                            {{s.steady_state_start, "steady state"}},
                            {{0, s.settle_threshold, settle.str()}}};
  std::vector<RunTraces> traces;
  for (const HoldRunResult& r : runs) traces.push_back(r.traces);
  const HoldTrajectory& tr = *runs.front().trajectory;
  write_error_band_figure(dir, fig, traces, runs.size() == 1 ? RawNorms{tr.t, {hold_error_norms(tr)}} : RawNorms{},
                          outputs);
}

}  // namespace hinf::sim
