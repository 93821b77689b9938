// Helpers shared by the subcommands: loading inputs, printing numbers and reports.
#pragma once
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <functional>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "hinf/synth/api.hpp"
#include "hinf/synth/synthesis.hpp"
#include "verbose_log.hpp"

namespace hinf::cli {

inline constexpr double kPi = 3.14159265358979323846;

// The positional pair CONFIG GAINS of the subcommands that read a config and a gains file.
struct ConfigGainsArgs {
  std::string config;
  std::string gains;
};
// Registers both positionals (required) on `cmd`; the values are there once parsed.
std::shared_ptr<ConfigGainsArgs> add_config_gains_args(CLI::App& cmd, const std::string& gains_help);

// "%.10g"
std::string num(double v);
// --format yaml|mat of the file solve and kalman write (default: mat for an output ending in
// ".mat", else yaml).
void add_format_option(CLI::App& cmd, std::string& format);
// The bytes of that file: the YAML as it is, or a MAT-file of the same keys
// (hinf/matfile/mat_file.hpp; docs/file-formats.md "MATLAB files").
std::string file_bytes(const synth::SolveOutcome& r, const std::string& format, const std::string& output);
// solve's and kalman's end: the file written to `output` (or stdout) in `format`, then the JSON
// (--json, with the output path) or the report, unless `quiet`.
void deliver_solved(const synth::SolveOutcome& r, const std::string& output, const std::string& format,
                    const std::string& config, bool json, bool quiet);
// Output paths (docs/cli.md): "-" is stdout, which then carries the file's bytes alone (the
// report goes to stderr). Otherwise the file is written atomically, never over `inputs`.
void write_output(const std::string& path, const std::string& bytes, const std::vector<std::string>& inputs);
// Where the text report goes: stdout, or stderr when `output` is "-".
std::ostream& report_stream(const std::string& output);
// -o - with --json: both want stdout; Error(InvalidInput) naming them.
void require_one_use_of_stdout(const std::string& output, bool json);
// -q/--quiet on a subcommand: no report on success (errors and --json are still printed).
void add_quiet_flag(CLI::App& cmd, bool& quiet);
// -v/--verbose on the subcommands that run no synthesis (docs/cli.md): each stage on stderr as
// it ends, with its wall time ("hinf-synth: verify: read configs/x.yaml (0.004 s)"); silent
// when not enabled.
class Stages {
 public:
  Stages(bool enabled, std::string subcommand) : enabled_(enabled), subcommand_(std::move(subcommand)) {}
  // f() timed and logged as `stage`; its result returned.
  template <class F>
  auto operator()(const std::string& stage, F&& f) const {
    const auto start = std::chrono::steady_clock::now();
    if constexpr (std::is_void_v<decltype(f())>) {
      f();
      log(stage, start);
    } else {
      auto result = f();
      log(stage, start);
      return result;
    }
  }
  // One line without a time (a sweep's point).
  void line(const std::string& text) const;
  bool enabled() const { return enabled_; }

 private:
  void log(const std::string& stage, std::chrono::steady_clock::time_point start) const;
  bool enabled_;
  std::string subcommand_;
};
// -v/--verbose, `what` it prints.
void add_verbose_flag(CLI::App& cmd, bool& verbose, const std::string& what = "each stage and its wall time on stderr");
// -v: the verbose account of a synthesis (coefficient ranges, sizes, the iteration table) on
// stderr through `log`, which must outlive the observers; none when `enabled` is false.
synth::JobObservers verbose_observers(bool enabled, std::optional<VerboseLog>& log);

using Json = nlohmann::ordered_json;  // keys in the order written
// --json: one line of JSON on stdout (a path that is not UTF-8 with U+FFFD rather than refused).
void print_json(const Json& j);
// A job's JSON (one line, synth outcomes' `json`) with the paths the command wrote appended
// as string keys (e.g. {"output", path}).
void print_json(const std::string& json_line, const std::vector<std::pair<std::string, std::string>>& paths = {});
// A PNG drawn by gnuplot from CSV data (sweep --plot, compare --plot): `script(data_path,
// png_path)` is the gnuplot script; the data and script are scratch files beside `png`,
// removed on return; the PNG is written atomically and never replaces one of `inputs`.
// Error(InvalidInput) if gnuplot cannot run or draws nothing.
void write_png_by_gnuplot(const std::string& png, const std::string& csv,
                          const std::function<std::string(const std::string&, const std::string&)>& script,
                          const std::vector<std::string>& inputs);
// The --verbose iteration table (a header whenever a new SDP starts), printed through a
// VerboseLog that outlives it.
class IterationTable {
 public:
  explicit IterationTable(VerboseLog& log) : log_(&log) {}
  void operator()(const synth::IterationReport& r);

 private:
  // A line per Newton iteration only after this many seconds without a line (large
  // problems, whose centrings take minutes), so that -v shows progress within seconds.
  static constexpr double kQuietSeconds = 2.0;
  // The measured time estimate is printed once the first Newton iteration has ended, if it
  // took at least this long.
  static constexpr double kEstimateAfterSeconds = 1.0;
  // A line while a Newton iteration's Hessian is assembled, and the estimate once the
  // first iteration has ended; true when the report was handled here.
  bool heartbeat(const sdp::Progress& r);
  VerboseLog* log_;
  bool estimated_ = false;
  bool started_ = false;
  synth::SolveStage stage_ = synth::SolveStage::Synthesis;
  double last_line_s_ = 0;
  int last_phase_ = 0;
};

}  // namespace hinf::cli
