// PNG plots of a run by gnuplot (Debian's gnuplot, run as a subprocess on a generated
// script; its exit status is checked): position and velocity error norms against time per
// filter (the paper's figures 2–5, 7) and the thrust history (figure 6).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hinf/common/atomic_file.hpp"
#include "hinf/sim/run.hpp"

namespace hinf::sim {

class PlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs the gnuplot script and checks that it drew every png (names: the files' names, for
// messages). Throws PlotError.
void run_plot_script(const std::string& script_path, const std::vector<std::string>& png,
                     const std::vector<std::string>& names);

// Draws DIR/position_error.png, DIR/velocity_error.png, DIR/thrust.png into temporaries of
// `outputs` (renamed with the run's other outputs by outputs.commit()): per filter the moving
// RMS of the error norm (plot_trace_settings) — run 0's over its raw trace in a lighter tone,
// or with several runs their median and 5–95 % band —, the convergence threshold and the
// steady-state start marked, scenario (`title`), seed and run count in the titles; the thrust
// of run 0. `results[0]` must hold its trajectory. Returns the file names. Throws PlotError.
std::vector<std::string> write_plots(const std::string& dir, const std::vector<RunResult>& results,
                                     const Scenario& scenario, const std::string& title, std::uint64_t seed,
                                     AtomicFileSet& outputs);

// The moving RMS of a run's error norms at the instants t (at most kPlotTracePoints of them):
// rms[f][q] for filter f and norm q of an error-band figure.
struct RunTraces {
  std::vector<double> t;
  std::vector<std::vector<std::vector<double>>> rms;  // [filter][norm][instant]
};

// A run's traces from its error norms at every sample — filter f's norm q at t[f][k] is
// norms[f][q][k] —: the moving RMS over `window` s (moving_rms_samples, NaN from a norm's first
// NaN on) at every stride-th sample of the filter with the most samples, stride such that there
// are at most kPlotTracePoints; a filter's shorter trace padded with NaN.
RunTraces run_traces(const std::vector<std::vector<double>>& t,
                     const std::vector<std::vector<std::vector<double>>>& norms, double window);

// Run 0's error norms at every sample: norms[f][q][k] at t[k] (the raw traces under the moving
// RMS when a campaign has one run).
struct RawNorms {
  std::vector<double> t;
  std::vector<std::vector<std::vector<double>>> norms;  // [filter][norm][sample]
};

// A figure of error norms against time (docs/experiments.md "Plots"), one panel per norm on a
// log scale: per filter its moving RMS over `window_s` — run 0's over its raw norm in a lighter
// tone (one run) or the median of the runs over their 5–95 % band (several) —, vertical marks
// (the steady-state window) and thresholds, the window and the run count in the title.
struct ErrorBandFigure {
  std::string file;                                   // "error_norms.png"
  std::string title;                                  // plot_title: scenario, seed, runs
  std::vector<std::string> filters;                   // names; drawn in this order, colours by index
  std::vector<std::string> norms;                     // the panels' y labels, with units
  double window_s = 0;
  std::vector<std::pair<double, std::string>> marks;  // vertical lines: (t, label)
  struct Threshold {
    std::size_t norm;  // the panel
    double value;
    std::string label;
  };
  std::vector<Threshold> thresholds;  // horizontal lines (a settle threshold)
};

// Draws DIR/fig.file into a temporary of `outputs` from every run's traces (runs[0] first) and
// run 0's raw norms. Throws PlotError.
void write_error_band_figure(const std::string& dir, const ErrorBandFigure& fig, const std::vector<RunTraces>& runs,
                             const RawNorms& raw, AtomicFileSet& outputs);

// The band of one filter's trace over the runs, per instant: the median and the 5 % and 95 %
// nearest-rank quantiles of the runs' values that are not NaN (NaN where every run's is).
struct TraceBand {
  std::vector<double> p05, median, p95;
};
TraceBand trace_band(const std::vector<const std::vector<double>*>& runs);

}  // namespace hinf::sim
