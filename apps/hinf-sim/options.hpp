// hinf-sim's command line, shared by the scenario families (main.cpp, tumbling_hold.cpp).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace hinf::sim_cli {

struct Options {
  std::string scenario_path, out_dir;
  long runs = 1;
  std::uint64_t seed = 1;
  int jobs = 1;
  std::optional<double> duration;
  bool no_plots = false, quiet = false, verbose = false;
};

// Creates the run directory (and its parents): Error(InvalidInput) naming it if it cannot.
void create_output_directory(const std::string& dir);

// --duration T for a scenario sampled at `sample_time`: T if it is a whole number (≥ 1) of
// samples, else Error(InvalidInput) naming --duration.
double checked_duration(double duration, double sample_time);

// A scenario family's three stages, each error reported on stderr with its exit code: load
// (hinf::Error: its code), simulate (std::invalid_argument — a runtime filter or controller
// refusing its settings — exit 2; SimulationError exit 4), write (hinf::Error, PlotError:
// exit 2). 0 when all three complete.
int run_stages(const std::function<void()>& load, const std::function<void()>& simulate,
               const std::function<void()>& write);

// Monte-Carlo progress on stderr (a bar), or nothing.
std::function<void(long, long)> progress_bar(bool enabled);

// A `scenario: tumbling_hold` run (docs/experiments.md "Seed 004"): its exit code.
int run_tumbling_hold(const Options& o, const std::string& scenario_text);

// A `scenario: gps_ins_relative` run (docs/experiments.md "Seed 003"): its exit code.
int run_gps_ins(const Options& o, const std::string& scenario_text);

// A `scenario: gyroless_attitude` run (docs/experiments.md "Seed 002"): its exit code.
int run_gyroless_attitude(const Options& o, const std::string& scenario_text);

}  // namespace hinf::sim_cli
