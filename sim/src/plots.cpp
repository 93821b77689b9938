#include "hinf/sim/plots.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <map>
#include <sstream>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/gnuplot.hpp"

namespace hinf::sim {
namespace {

const std::map<std::string, std::string> kColour = {
    {"hinf", "#d62728"}, {"published", "#ff7f0e"}, {"ekf", "#1f77b4"}, {"ekf_no_control", "#7f7f7f"}, {"rekf", "#2ca02c"}};

std::string colour(const std::string& name) {
  const auto it = kColour.find(name);
  return it == kColour.end() ? "#000000" : it->second;
}

std::string quoted(const std::string& s) { return gnuplot_quoted(s); }

// The colour mixed with white (weight `white` of white): the raw trace under its moving RMS.
std::string lighter(const std::string& hex, double white) {
  std::ostringstream os;
  os << '#' << std::hex;
  for (int i = 0; i < 3; ++i) {
    const int c = std::stoi(hex.substr(1 + 2 * i, 2), nullptr, 16);
    const int mixed = static_cast<int>(c + white * (255 - c) + 0.5);
    os << (mixed < 16 ? "0" : "") << mixed;
  }
  return os.str();
}

// raw.dat: t, thrust (3), then |e_p|, |e_v| per filter (run 0, every sample).
std::string raw_data(const Trajectory& tr) {
  std::ostringstream os;
  os.precision(9);
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    os << tr.t[k] << ' ' << tr.thrust[k](0) << ' ' << tr.thrust[k](1) << ' ' << tr.thrust[k](2);
    for (const auto& f : tr.filters) {
      const Vector6 e = f.estimate[k] - tr.truth[k];
      if (e.allFinite()) os << ' ' << e.head<3>().norm() << ' ' << e.tail<3>().norm();
      else os << " NaN NaN";
    }
    os << '\n';
  }
  return os.str();
}

// band.dat: t, then per filter and quantity (|e_p|, |e_v|) the median, 5 % and 95 % of the
// runs' moving RMS (column 2 + 6 f + 3 q + {0, 1, 2}).
std::string band_data(const std::vector<RunResult>& results) {
  std::vector<TraceBand> bands;  // [2 f + q]
  for (std::size_t f = 0; f < results.front().filters.size(); ++f)
    for (const bool position : {true, false}) {
      std::vector<const std::vector<double>*> runs;
      for (const RunResult& r : results)
        runs.push_back(position ? &r.filters[f].position_rms_trace : &r.filters[f].velocity_rms_trace);
      bands.push_back(trace_band(runs));
    }
  std::ostringstream os;
  os.precision(9);
  const std::vector<double>& t = results.front().trace_t;
  for (std::size_t i = 0; i < t.size(); ++i) {
    os << t[i];
    for (const TraceBand& b : bands) os << ' ' << b.median[i] << ' ' << b.p05[i] << ' ' << b.p95[i];
    os << '\n';
  }
  return os.str();
}

struct PlotFiles {
  std::string raw, band;
};

// One error figure: per filter (drawing order: the noisiest LTI traces first) run 0's raw
// norm lighter (one run) or the 5–95 % band (several), then the moving RMS or the median.
void error_figure(std::ostringstream& gp, const std::vector<RunResult>& results, const Scenario& s,
                  const std::string& heading, const PlotFiles& data, int quantity, const std::string& out) {
  const Trajectory& tr = *results.front().trajectory;
  const bool band = results.size() > 1;
  std::vector<std::size_t> order;
  for (const char* name : {"published", "hinf", "ekf_no_control", "ekf", "rekf"})
    for (std::size_t f = 0; f < tr.filters.size(); ++f)
      if (tr.filters[f].name == name) order.push_back(f);
  gp << "set output " << quoted(out) << "\nset logscale y\nset format y '10^{%L}'\n"
     << "set title " << quoted(heading) << " noenhanced\n";
  const MetricSettings ms = s.metric_settings();
  gp << "unset arrow\nunset label\n"
     << "set arrow from first " << ms.steady_state_start_s << ", graph 0 to first " << ms.steady_state_start_s
     << ", graph 1 nohead dt 3 lc rgb '#555555'\n"
     << "set label 'steady state' at first " << ms.steady_state_start_s << ", graph 0.96 offset 0.5,0 font ',9'\n";
  if (quantity == 0)
    gp << "set arrow from graph 0, first " << ms.converge_threshold_m << " to graph 1, first " << ms.converge_threshold_m
       << " nohead dt 2 lc rgb '#555555'\n"
       << "set label 'convergence " << ms.converge_threshold_m << " m' at graph 0.01, first "
       << ms.converge_threshold_m << " offset 0,0.6 font ',9'\n";
  gp << "plot ";
  std::string sep;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t f = order[i];
    const std::string c = colour(tr.filters[f].name);
    const int col = 2 + 6 * static_cast<int>(f) + 3 * quantity;
    if (band)
      gp << sep << quoted(data.band) << " using 1:" << col + 1 << ":" << col + 2
         << " with filledcurves fs transparent solid 0.18 noborder lc rgb " << quoted(c) << " notitle";
    else
      gp << sep << quoted(data.raw) << " using 1:" << 5 + 2 * static_cast<int>(f) + quantity
         << " with lines lw 0.6 lc rgb " << quoted(lighter(c, 0.65)) << " notitle";
    sep = ", ";
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t f = order[i];
    const int col = 2 + 6 * static_cast<int>(f) + 3 * quantity;
    gp << sep << quoted(data.band) << " using 1:" << col << " with lines lw 2.2 dt " << 1 + i % 5 << " lc rgb "
       << quoted(colour(tr.filters[f].name)) << " title " << quoted(tr.filters[f].name) << " noenhanced";
  }
  gp << "\nunset logscale y\nset format y '%g'\nunset arrow\nunset label\n";
}

// The gnuplot script drawing png[0..2] (position error, velocity error, thrust).
std::string plot_script(const std::vector<RunResult>& results, const Scenario& s, const std::string& title,
                        std::uint64_t seed, const PlotFiles& data, const std::vector<std::string>& png) {
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,560 enhanced font 'Sans,11'\n"
     << "set grid\nset key outside right top\nset xlabel 'time (s)'\n"
     << "set datafile missing 'NaN'\n";
  const PlotTraceSettings p = plot_trace_settings(s);
  std::ostringstream what;
  what.precision(4);
  what << "moving RMS over " << p.window_s << " s, "
       << (results.size() > 1 ? "median and 5–95 % of " + std::to_string(results.size()) + " runs"
                              : std::string("run 0 (raw norm lighter)"))
       << ", seed " << seed;
  error_figure(gp, results, s, title + ": position error |r̂ − r| (m), " + what.str(), data, 0, png[0]);
  error_figure(gp, results, s, title + ": velocity error |v̂ − v| (m/s), " + what.str(), data, 1, png[1]);
  gp << "set output " << quoted(png[2]) << "\nset ylabel 'thrust (N)'\nset title "
     << quoted(title + ": thrust u = K x, run 0, seed " + std::to_string(seed)) << " noenhanced\n"
     << "plot " << quoted(data.raw) << " using 1:2 with lines lw 1.5 title 'F_x', " << quoted(data.raw)
     << " using 1:3 with lines lw 1.5 title 'F_y', " << quoted(data.raw) << " using 1:4 with lines lw 1.5 title 'F_z'\n"
     << "set output\n";
  return gp.str();
}

}  // namespace

void run_plot_script(const std::string& script, const std::vector<std::string>& png,
                     const std::vector<std::string>& names) {
  namespace fs = std::filesystem;
  const int rc = run_gnuplot(script);
  if (rc != 0)
    throw PlotError(rc < 0 ? "cannot run gnuplot (is the gnuplot package installed?); use --no-plots to skip plots"
                           : "gnuplot failed with exit status " + std::to_string(rc));
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::error_code ec;
    if (!fs::exists(png[i], ec) || fs::file_size(png[i], ec) == 0)
      throw PlotError("gnuplot produced no output for " + names[i]);
  }
}

TraceBand trace_band(const std::vector<const std::vector<double>*>& runs) {
  TraceBand b;
  const std::size_t n = runs.empty() ? 0 : runs.front()->size();
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> v;
    for (const auto* r : runs)
      if (i < r->size() && !std::isnan((*r)[i])) v.push_back((*r)[i]);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    b.p05.push_back(v.empty() ? nan : nearest_rank_quantile(v, 0.05));
    b.median.push_back(v.empty() ? nan : nearest_rank_quantile(v, 0.5));
    b.p95.push_back(v.empty() ? nan : nearest_rank_quantile(v, 0.95));
  }
  return b;
}

std::vector<std::string> write_plots(const std::string& dir, const std::vector<RunResult>& results,
                                     const Scenario& scenario, const std::string& title, std::uint64_t seed,
                                     AtomicFileSet& outputs) {
  namespace fs = std::filesystem;
  const std::vector<std::string> names = {"position_error.png", "velocity_error.png", "thrust.png"};
  std::vector<std::string> png;
  for (const auto& n : names) png.push_back(outputs.reserve((fs::path(dir) / n).string()));
  AtomicFileSet scratch;  // never committed: removed on return
  PlotFiles data;
  data.raw = scratch.add((fs::path(dir) / "plot.dat").string(), raw_data(*results.front().trajectory));
  data.band = scratch.add((fs::path(dir) / "band.dat").string(), band_data(results));
  const std::string script =
      scratch.add((fs::path(dir) / "plot.gp").string(), plot_script(results, scenario, title, seed, data, png));
  run_plot_script(script, png, names);
  return names;
}

}  // namespace hinf::sim
