#include "hinf/sim/plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/gnuplot.hpp"
#include "hinf/sim/metrics.hpp"

namespace hinf::sim {
namespace {

// The Hill filters' colours, by name (hinf-sim's figures of the paper); other families' filters
// take kPalette's by index.
const std::map<std::string, std::string> kColour = {
    {"hinf", "#d62728"}, {"published", "#ff7f0e"}, {"ekf", "#1f77b4"}, {"ekf_no_control", "#7f7f7f"}, {"rekf", "#2ca02c"}};
constexpr const char* kPalette[10] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                      "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
constexpr int kDashTypes = 5;  // gnuplot's dt 1 … 5, cycled so that overlapping curves stay apart

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

// A dotted vertical line at time t, its label at height label_y of the panel (graph units).
void vertical_mark(std::ostream& gp, double t, const std::string& label, double label_y) {
  gp << "set arrow from first " << t << ", graph 0 to first " << t << ", graph 1 nohead dt 3 lc rgb '#555555'\n"
     << "set label " << quoted(label) << " at first " << t << ", graph " << label_y << " offset 0.5,0 font ',9'\n";
}

// A dashed horizontal line at y = value (a threshold), its label at the left.
void horizontal_mark(std::ostream& gp, double value, const std::string& label) {
  gp << "set arrow from graph 0, first " << value << " to graph 1, first " << value << " nohead dt 2 lc rgb '#555555'\n"
     << "set label " << quoted(label) << " at graph 0.01, first " << value << " offset 0,0.6 font ',9'\n";
}

// t, then per band its median, 5 % and 95 % (bands in the order f Q + q: band file columns
// 2 + 3 (f Q + q) + {0, 1, 2}).
std::string band_table(const std::vector<double>& t, const std::vector<TraceBand>& bands) {
  std::ostringstream os;
  os.precision(9);
  for (std::size_t i = 0; i < t.size(); ++i) {
    os << t[i];
    for (const TraceBand& b : bands) os << ' ' << b.median[i] << ' ' << b.p05[i] << ' ' << b.p95[i];
    os << '\n';
  }
  return os.str();
}

// Where one panel's curves are (error_curves): the band file (band_table) and, for one run, the
// raw file (filter f's norm q in column raw_first + f Q + q).
struct ErrorCurves {
  std::string band, raw;  // raw empty: several runs, their band drawn
  int norms = 1;          // Q
  int raw_first = 2;
  std::vector<std::string> names, colours;  // per filter, in the files' order
  std::vector<std::size_t> order;           // drawing order (the noisiest first)
};

// The `plot` arguments of norm q: per filter (in c.order) its raw norm lighter or its band, then
// over them all its moving RMS or median, in its colour and its own dash type, with its name.
std::string error_curves(const ErrorCurves& c, int q) {
  std::ostringstream gp;
  std::string sep;
  const auto band_column = [&](std::size_t f) { return 2 + 3 * (static_cast<int>(f) * c.norms + q); };
  for (const std::size_t f : c.order) {
    if (c.raw.empty())
      gp << sep << quoted(c.band) << " using 1:" << band_column(f) + 1 << ":" << band_column(f) + 2
         << " with filledcurves fs transparent solid 0.18 noborder lc rgb " << quoted(c.colours[f]) << " notitle";
    else
      gp << sep << quoted(c.raw) << " using 1:" << c.raw_first + static_cast<int>(f) * c.norms + q
         << " with lines lw 0.6 lc rgb " << quoted(lighter(c.colours[f], 0.65)) << " notitle";
    sep = ", ";
  }
  for (std::size_t i = 0; i < c.order.size(); ++i) {
    const std::size_t f = c.order[i];
    gp << sep << quoted(c.band) << " using 1:" << band_column(f) << " with lines lw 2.2 dt " << 1 + i % kDashTypes
       << " lc rgb " << quoted(c.colours[f]) << " title " << quoted(c.names[f]) << " noenhanced";
  }
  return gp.str();
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

// band.dat: per filter and quantity (|e_p|, |e_v|) the band of the runs' moving RMS.
std::string band_data(const std::vector<RunResult>& results) {
  std::vector<TraceBand> bands;  // [2 f + q]
  for (std::size_t f = 0; f < results.front().filters.size(); ++f)
    for (const bool position : {true, false}) {
      std::vector<const std::vector<double>*> runs;
      for (const RunResult& r : results)
        runs.push_back(position ? &r.filters[f].position_rms_trace : &r.filters[f].velocity_rms_trace);
      bands.push_back(trace_band(runs));
    }
  return band_table(results.front().trace_t, bands);
}

struct PlotFiles {
  std::string raw, band;
};

// One error figure: per filter (drawing order: the noisiest LTI traces first) run 0's raw
// norm lighter (one run) or the 5–95 % band (several), then the moving RMS or the median.
void error_figure(std::ostringstream& gp, const std::vector<RunResult>& results, const Scenario& s,
                  const std::string& heading, const PlotFiles& data, int quantity, const std::string& out) {
  const Trajectory& tr = *results.front().trajectory;
  ErrorCurves curves{data.band, results.size() > 1 ? "" : data.raw, 2, 5, {}, {}, {}};  // raw: |e_p| in column 5
  for (const auto& f : tr.filters) {
    curves.names.push_back(f.name);
    curves.colours.push_back(colour(f.name));
  }
  for (const char* name : {"published", "hinf", "ekf_no_control", "ekf", "rekf"})
    for (std::size_t f = 0; f < tr.filters.size(); ++f)
      if (tr.filters[f].name == name) curves.order.push_back(f);
  gp << "set output " << quoted(out) << "\nset logscale y\nset format y '10^{%L}'\n"
     << "set title " << quoted(heading) << " noenhanced\n";
  const MetricSettings ms = s.metric_settings();
  gp << "unset arrow\nunset label\n";
  vertical_mark(gp, ms.steady_state_start_s, "steady state", 0.96);
  if (quantity == 0) {
    std::ostringstream label;
    label << "convergence " << ms.converge_threshold_m << " m";
    horizontal_mark(gp, ms.converge_threshold_m, label.str());
  }
  gp << "plot " << error_curves(curves, quantity)
     << "\nunset logscale y\nset format y '%g'\nunset arrow\nunset label\n";
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

// The raw file of write_error_band_figure: t, then filter f's norm q in column 2 + f Q + q.
std::string raw_norms_table(const RawNorms& raw) {
  std::ostringstream os;
  os.precision(9);
  for (std::size_t k = 0; k < raw.t.size(); ++k) {
    os << raw.t[k];
    for (const auto& filter : raw.norms)
      for (const auto& norm : filter) {
        if (k < norm.size() && std::isfinite(norm[k])) os << ' ' << norm[k];
        else os << " NaN";
      }
    os << '\n';
  }
  return os.str();
}

// The band file of write_error_band_figure: per filter and norm the band of the runs' traces.
std::string error_band_table(const std::vector<RunTraces>& runs, std::size_t filters, std::size_t norms) {
  std::vector<TraceBand> bands;  // [f Q + q]
  for (std::size_t f = 0; f < filters; ++f)
    for (std::size_t q = 0; q < norms; ++q) {
      std::vector<const std::vector<double>*> traces;
      for (const RunTraces& r : runs) traces.push_back(&r.rms[f][q]);
      bands.push_back(trace_band(traces));
    }
  return band_table(runs.front().t, bands);
}

// The gnuplot script of write_error_band_figure.
std::string error_band_script(const ErrorBandFigure& fig, long runs, const ErrorCurves& curves,
                              const std::string& png) {
  const int panels = static_cast<int>(fig.norms.size());
  std::ostringstream what;
  what.precision(4);
  what << fig.title << ": error norms, moving RMS over " << fig.window_s << " s, "
       << (runs > 1 ? "median and 5–95 % of " + std::to_string(runs) + " runs" : std::string("run 0 (raw norm lighter)"));
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000," << 200 + 220 * panels << " enhanced font 'Sans,10'\n"
     << "set grid\nset lmargin 12\nset rmargin 24\nset datafile missing 'NaN'\n"
     << "set logscale y\nset format y '10^{%L}'\n";
  const auto marks = [&](int q) {
    std::ostringstream m;
    m << "unset arrow\nunset label\n";
    for (const auto& [t, label] : fig.marks) vertical_mark(m, t, label, 0.92);
    for (const ErrorBandFigure::Threshold& h : fig.thresholds)
      if (h.norm == static_cast<std::size_t>(q)) horizontal_mark(m, h.value, h.label);
    return m.str();
  };
  gp << gnuplot_stacked_figure(
            png, what.str(), panels, [&](int q) { return fig.norms[static_cast<std::size_t>(q)]; },
            [&](int q) { return error_curves(curves, q); }, marks)
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

RunTraces run_traces(const std::vector<std::vector<double>>& t,
                     const std::vector<std::vector<std::vector<double>>>& norms, double window) {
  std::size_t longest = 0;
  for (std::size_t f = 0; f < t.size(); ++f)
    if (t[f].size() > t[longest].size()) longest = f;
  const long n = static_cast<long>(t.empty() ? 0 : t[longest].size());
  const long stride = std::max(1L, (n + kPlotTracePoints - 1) / kPlotTracePoints);
  RunTraces out;
  for (long k = 0; k < n; k += stride) out.t.push_back(t[longest][static_cast<std::size_t>(k)]);
  for (std::size_t f = 0; f < norms.size(); ++f) {
    out.rms.emplace_back();
    for (const std::vector<double>& norm : norms[f]) {
      std::vector<double> r = moving_rms_samples(t[f], norm, window, stride);
      r.resize(out.t.size(), std::numeric_limits<double>::quiet_NaN());
      out.rms.back().push_back(std::move(r));
    }
  }
  return out;
}

void write_error_band_figure(const std::string& dir, const ErrorBandFigure& fig, const std::vector<RunTraces>& runs,
                             const RawNorms& raw, AtomicFileSet& outputs) {
  namespace fs = std::filesystem;
  const std::size_t nf = fig.filters.size(), nq = fig.norms.size();
  if (runs.empty() || nf == 0 || nq == 0) throw PlotError("no error norms to draw in " + fig.file);
  const std::string png = outputs.reserve((fs::path(dir) / fig.file).string());
  const std::string stem = fs::path(fig.file).stem().string();
  AtomicFileSet scratch;  // never committed: removed on return
  ErrorCurves curves;
  curves.norms = static_cast<int>(nq);
  curves.band = scratch.add((fs::path(dir) / (stem + "_band.dat")).string(), error_band_table(runs, nf, nq));
  if (runs.size() == 1) curves.raw = scratch.add((fs::path(dir) / (stem + ".dat")).string(), raw_norms_table(raw));
  curves.names = fig.filters;
  for (std::size_t f = 0; f < nf; ++f) {
    curves.colours.push_back(kPalette[f % std::size(kPalette)]);
    curves.order.push_back(f);
  }
  const std::string script = scratch.add((fs::path(dir) / (stem + ".gp")).string(),
                                         error_band_script(fig, static_cast<long>(runs.size()), curves, png));
  run_plot_script(script, {png}, {fig.file});
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
