// hinf-sim's command line and what the scenario families share (main.cpp, tumbling_hold.cpp,
// gps_ins.cpp, gyroless_attitude.cpp, manoeuvring_target.cpp).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hinf/common/atomic_file.hpp"
#include "hinf/sim/monte_carlo.hpp"
#include "hinf/sim/run_directory.hpp"
#include "hinf/sim/status_log.hpp"

namespace hinf::sim_cli {

struct Options {
  std::string scenario_path, out_dir;
  long runs = 1;
  std::uint64_t seed = 1;
  int jobs = 1;
  std::optional<double> duration;
  bool no_plots = false, quiet = false, verbose = false;
};

// A scenario family's three stages, each error reported on stderr with its exit code: load
// (hinf::Error: its code), simulate (std::invalid_argument — a runtime filter or controller
// refusing its settings — exit 2; SimulationError exit 4), write (hinf::Error, PlotError:
// exit 2). 0 when all three complete.
int run_stages(const std::function<void()>& load, const std::function<void()>& simulate,
               const std::function<void()>& write);

// The library's status lines on stderr ("hinf-sim: synthesising from PATH ..."), or nothing.
hinf::sim::StatusLog status_log(bool enabled);

// Monte-Carlo progress on stderr (a bar), or nothing.
std::function<void(long, long)> progress_bar(bool enabled);

// The Monte-Carlo runs of a scenario family with --runs, --jobs, --seed and the progress bar
// (hinf::sim::run_family_campaign).
template <class Stats, class Sample, class RunOne>
std::vector<std::vector<Stats>> run_family_campaign(const Options& o, std::vector<std::vector<Sample>>* samples,
                                                    const RunOne& run_one) {
  return sim::run_family_campaign<Stats, Sample>(o.runs, o.jobs, o.seed, samples, run_one,
                                         progress_bar(!o.quiet && o.runs > 1));
}

// A scenario family's run directory in --out (hinf::sim::write_run_directory): `inputs`, the
// files the scenario names, are protected with the scenario file itself; unless --no-plots or
// `plots_enabled` is false, `plots(title, outputs)` draws into temporaries of the same set
// (title: the scenario file's stem).
void write_run_directory(const Options& o, const std::vector<std::pair<std::string, std::string>>& files,
                         const std::vector<std::string>& inputs, bool plots_enabled,
                         const std::function<void(const std::string& title, hinf::AtomicFileSet& outputs)>& plots);

// A `scenario: tumbling_hold` run (docs/experiments.md "Seed 004"): its exit code.
int run_tumbling_hold(const Options& o, const std::string& scenario_text);

// A `scenario: gps_ins_relative` run (docs/experiments.md "Seed 003"): its exit code.
int run_gps_ins(const Options& o, const std::string& scenario_text);

// A `scenario: gyroless_attitude` run (docs/experiments.md "Seed 002"): its exit code.
int run_gyroless_attitude(const Options& o, const std::string& scenario_text);

// A `scenario: manoeuvring_target` run (docs/experiments.md "Seed 001"): its exit code.
int run_manoeuvring_target(const Options& o, const std::string& scenario_text);

}  // namespace hinf::sim_cli
