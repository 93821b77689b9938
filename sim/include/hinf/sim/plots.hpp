// PNG plots of a run by gnuplot (Debian's gnuplot, run as a subprocess on a generated
// script; its exit status is checked): position and velocity error norms against time per
// filter (the paper's figures 2–5, 7) and the thrust history (figure 6).
#pragma once
#include <stdexcept>
#include <cstdint>
#include <string>
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

// The band of one filter's trace over the runs, per instant: the median and the 5 % and 95 %
// nearest-rank quantiles of the runs' values that are not NaN (NaN where every run's is).
struct TraceBand {
  std::vector<double> p05, median, p95;
};
TraceBand trace_band(const std::vector<const std::vector<double>*>& runs);

}  // namespace hinf::sim
