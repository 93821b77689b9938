// The simulation API every front end binds to (hinf-sim, and the coming Python module and
// campaign shards): a scenario's text in, a campaign's run directory out — in memory first,
// files second. Each experiment family (docs/experiments.md: the Hill/CW experiments,
// tumbling_hold, gps_ins_relative, gyroless_attitude, manoeuvring_target, linear_plant) implements Family
// in its own folder sim/families/<name>/ and is listed once in sim/src/family_registry.cpp.
// Nothing here prints or exits.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hinf/common/atomic_file.hpp"
#include "hinf/sim/run_directory.hpp"
#include "hinf/sim/status_log.hpp"

namespace hinf::sim {

// What a campaign is asked for: the scenario (read once by the caller) and hinf-sim's options.
struct CampaignRequest {
  std::string scenario_path;  // for messages, relative paths and summary.json
  std::string scenario_text;  // the scenario file's bytes
  long runs = 1;              // Monte-Carlo runs; run i uses derive_seed(seed, i)
  std::uint64_t seed = 1;
  int jobs = 1;                     // parallel runs
  std::optional<double> duration;   // overrides the scenario's (one rule: sim/scenario.hpp)
  StatusLog log;                    // status lines ("synthesising from PATH ..."), or none
  std::function<void(long done, long total)> progress;  // Monte-Carlo progress, or none
  // Announces each further campaign of a family that runs several (gps_ins_relative's table 1:
  // "campaign 2 of 3: table 1 at inertia_products_fraction = 0.3") before its progress; or none.
  std::function<void(const std::string& label)> on_campaign;
  // Polled before each Monte-Carlo run; true: no further run starts, and simulate() throws
  // SimulationError "interrupted" once the runs under way have ended (a front end's Ctrl-C).
  std::function<bool()> interrupted;
};

// A campaign's run directory, in memory.
struct CampaignResult {
  std::vector<std::pair<std::string, std::string>> files;  // (name, bytes): trajectory.csv, runs.csv, ...
  std::vector<std::string> inputs;  // the files the scenario names (never replaced by an output)
  bool plots = false;               // the scenario asks for plots and the family draws some
  // Draws the plots into temporaries of `outputs` (names in the run directory `out_dir`; title:
  // the scenario file's stem). Owns what it draws from. Throws PlotError.
  std::function<void(const std::string& out_dir, const std::string& title, AtomicFileSet& outputs)> draw_plots;
};

// An experiment family. simulate() throws hinf::Error (invalid scenario, gains, controller or
// synthesis: its code), std::invalid_argument (a runtime filter refusing the settings a
// scenario gave it: invalid input) or SimulationError (a run that cannot go on: numerical).
class Family {
 public:
  virtual ~Family() = default;
  virtual const char* name() const = 0;  // the scenario's `scenario:` value ("" for the Hill family)
  // Reads and validates a scenario of this family without running it (hinf::Error).
  virtual void parse(const std::string& scenario_text, const std::string& scenario_path) const = 0;
  virtual CampaignResult simulate(const CampaignRequest& request) const = 0;
};

// The family of a scenario's text (its `scenario:` key; absent: the Hill experiments). Throws
// Error(InvalidInput) naming an unknown family or text that is not a YAML map.
const Family& family_of(const std::string& scenario_text, const std::string& scenario_path);

// family_of(request's text).simulate(request).
CampaignResult simulate(const CampaignRequest& request);

// Writes `result` as the run directory `out_dir` (sim/run_directory.hpp): every file to a
// temporary, renamed together with the manifest; none replaces the scenario file or one of
// result.inputs; plots drawn unless `plots` is false; an earlier run's files there that this
// one did not write removed (returned). Throws hinf::Error or PlotError.
RunDirectoryReplaced write_campaign(const CampaignResult& result, const std::string& out_dir, const std::string& scenario_path,
                    bool plots);

}  // namespace hinf::sim
