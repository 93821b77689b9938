// PNG plots of a run by gnuplot (Debian's gnuplot, run as a subprocess on a generated
// script; its exit status is checked): position and velocity error norms against time per
// filter (the paper's figures 2–5, 7) and the thrust history (figure 6).
#pragma once
#include <stdexcept>
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
// `outputs` (renamed with the run's other outputs by outputs.commit()). Returns the file
// names. Throws PlotError.
std::vector<std::string> write_plots(const std::string& dir, const Trajectory& trajectory, const std::string& title,
                                     AtomicFileSet& outputs);

}  // namespace hinf::sim
