// hinf-sim's command line and where its lines go (main.cpp): the simulation itself is the
// library's (sim/family.hpp).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "hinf/sim/status_log.hpp"

namespace hinf::sim_cli {

struct Options {
  std::string scenario_path, out_dir;
  std::string old_out_dir;  // --out, the older spelling of -o/--output (docs/cli.md)
  long runs = 1;
  std::uint64_t seed = 1;
  int jobs = 1;
  std::optional<double> duration;
  bool no_plots = false, quiet = false, verbose = false;
  bool json = false;  // the run directory's description and summary.json on stdout (docs/experiments.md)
  std::string format = "csv";  // "mat": run.mat beside the CSV files
};

// The library's status lines on stderr ("hinf-sim: synthesising from PATH ..."), or nothing.
hinf::sim::StatusLog status_log(bool enabled);

// Monte-Carlo progress on stderr (a bar), or nothing.
std::function<void(long, long)> progress_bar(bool enabled);

}  // namespace hinf::sim_cli
