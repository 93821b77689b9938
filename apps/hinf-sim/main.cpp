// hinf-sim SCENARIO.yaml -o DIR [--runs N] [--seed S] [--jobs J] [--format csv|mat] [--json]
// Exit codes: 0 ok, 2 invalid input or unwritable output, 3 infeasible synthesis,
// 4 numerical failure (synthesis certificate, non-finite truth).
#include <CLI/CLI.hpp>
#include <hinf/common/error.hpp>

#include <charconv>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <new>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>
#include <unistd.h>

#include "hinf/common/input_file.hpp"
#include "hinf/matfile/mat_file.hpp"
#include "hinf/sim/family.hpp"
#include "hinf/sim/plots.hpp"
#include "hinf/sim/simulation_error.hpp"
#include "hinf/sim/summary_table.hpp"
#include "options.hpp"

namespace {

constexpr int kExitInvalid = 2;
constexpr int kExitNumerical = 4;

using hinf::sim_cli::Options;

// CLI11's own checks let "nan" through PositiveNumber (NaN <= 0 is false) and let an
// unsigned option wrap "-1" to 2^64 - 1.
const CLI::Validator kFinitePositive(
    [](const std::string& text) -> std::string {
      double v = 0;
      if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || !(v > 0))
        return "must be a finite number > 0, got '" + text + "'";
      return "";
    },
    "POSITIVE");
const CLI::Validator kWholeNumber(
    [](const std::string& text) -> std::string {
      std::uint64_t v = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (text.empty() || ec != std::errc() || end != text.data() + text.size())
        return "must be a whole number in [0, 18446744073709551615], got '" + text + "'";
      return "";
    },
    "UINT");

void add_options(CLI::App& app, Options& o) {
  app.add_option("scenario", o.scenario_path, "scenario file (YAML)")->required();
  auto* output = app.add_option("-o,--output", o.out_dir, "output directory (created if missing)");
  app.add_option("--out", o.old_out_dir, "the older spelling of -o/--output")->group("")->excludes(output);
  app.add_option("--runs", o.runs, "Monte-Carlo runs (run i uses the seed derived from (seed, i))")
      ->check(CLI::Range(1L, 1000000L));
  app.add_option("--seed", o.seed, "base seed, a whole number in [0, 2^64 - 1]")->check(kWholeNumber);
  o.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--jobs,-j", o.jobs, "parallel runs (default: hardware threads)")->check(CLI::Range(1, 4096));
  app.add_option("--duration", o.duration, "override the scenario's duration (s)")->check(kFinitePositive);
  app.add_flag("--no-plots", o.no_plots, "do not run gnuplot");
  app.add_flag("--quiet,-q", o.quiet, "no progress, no end-of-run table");
  app.add_flag("--verbose,-v", o.verbose, "report gains origin and synthesis progress");
  app.add_option("--format", o.format, "csv (default) or mat: also run.mat, every CSV table and the summary as MATLAB variables")
      ->check(CLI::IsMember({"csv", "mat"}));
  app.add_flag("--json", o.json, "print JSON (schema hinf-sim.run/1: the files written and summary.json) when done");
}

// --format mat: run.mat beside the run directory's files, a variable per table (trajectory,
// runs, …: a struct of columns named by the CSV's header) and `summary` (summary.json's object).
void add_mat_file(hinf::sim::CampaignResult& result) {
  hinf::matfile::Json variables = hinf::matfile::Json::object();
  for (const auto& [name, bytes] : result.files) {
    const std::string stem = std::filesystem::path(name).stem().string();
    if (std::filesystem::path(name).extension() == ".csv")
      variables[stem] = hinf::matfile::csv_columns(bytes, name);
    else if (name == "summary.json")
      variables["summary"] = hinf::matfile::Json::parse(bytes);
  }
  result.files.emplace_back("run.mat", hinf::matfile::mat_file_bytes(variables, "MATLAB 5.0 MAT-file, hinf-sim run"));
}

// --json: one line on stdout once the run directory is written: what it holds and the
// summary (summary.json's own object, numbers bit for bit).
void print_run_json(const hinf::sim::CampaignResult& result, const hinf::sim::RunDirectoryReplaced& replaced,
                    const Options& o) {
  using Json = nlohmann::ordered_json;
  Json j;
  j["schema"] = "hinf-sim.run/1";
  j["scenario"] = o.scenario_path;
  j["out"] = o.out_dir;
  j["files"] = Json::array();
  Json summary = nullptr;
  for (const auto& [name, bytes] : result.files) {
    j["files"].push_back(name);
    if (name == "summary.json") summary = Json::parse(bytes);
  }
  j["plots"] = result.plots && !o.no_plots;
  j["replaced_previous_run"] = replaced.previous_run;
  j["removed_previous_files"] = replaced.removed;
  j["summary"] = std::move(summary);
  std::cout << j.dump(-1, ' ', false, Json::error_handler_t::replace) << "\n";
}

// A run into a directory that held one (its manifest.txt) says so, with the files of that run
// this one did not write and removed.
void print_replaced(const hinf::sim::RunDirectoryReplaced& replaced, const std::string& dir) {
  std::cerr << "hinf-sim: note: " << dir << " held an earlier run; replaced";
  if (!replaced.removed.empty()) {
    std::cerr << " (removed its files this run did not write:";
    for (const std::string& name : replaced.removed) std::cerr << " " << name;
    std::cerr << ")";
  }
  std::cerr << "\n";
}

int run(int argc, char** argv) {
  CLI::App app{"hinf-sim: nonlinear relative-navigation experiments comparing the H∞ filter, the paper's "
               "published gains, EKFs and the REKF (docs/experiments.md)"};
  Options o;
  add_options(app, o);
  app.set_version_flag("--version", "hinf-sim " HINF_VERSION);
  app.footer("Example: hinf-sim configs/scenarios/paper-control.yaml -o out/paper --runs 20 --jobs 2\n"
             "Exit codes: 0 ok, 2 invalid input or unwritable output, 3 infeasible synthesis, 4 numerical failure "
             "(non-finite truth, synthesis certificate). Conventions: docs/cli.md.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "hinf-sim: error: " << e.what() << " (hinf-sim --help)\n";
    return kExitInvalid;
  }
  if (!o.old_out_dir.empty()) {
    o.out_dir = o.old_out_dir;
    std::cerr << "hinf-sim: note: --out is the older spelling of -o/--output; it will go in a later version\n";
  }
  if (o.out_dir.empty()) {
    std::cerr << "hinf-sim: error: --output is required (hinf-sim --help)\n";
    return kExitInvalid;
  }

  const auto fail = [](const std::string& what, hinf::ErrorCode code) {
    std::cerr << "hinf-sim: error: " << what << "\n";
    return hinf::exit_code(code);
  };
  hinf::sim::CampaignRequest request;
  request.scenario_path = o.scenario_path;
  request.runs = o.runs;
  request.seed = o.seed;
  request.jobs = o.jobs;
  request.duration = o.duration;
  request.log = hinf::sim_cli::status_log(o.verbose);
  request.progress = hinf::sim_cli::progress_bar(!o.quiet && o.runs > 1);
  if (!o.quiet) request.on_campaign = [](const std::string& label) { std::cerr << "hinf-sim: " << label << "\n"; };
  hinf::sim::CampaignResult result;
  try {  // the scenario read once; its family (sim/family.hpp) runs the campaign in memory
    request.scenario_text = hinf::read_input_file(o.scenario_path, "scenario", hinf::kMaxScenarioBytes);
    result = hinf::sim::simulate(request);
  } catch (const hinf::Error& e) {  // scenario, gains, controller, synthesis: its own code
    return fail(e.what(), e.code());
  } catch (const std::invalid_argument& e) {  // a runtime filter refusing its settings
    return fail(e.what(), hinf::ErrorCode::InvalidInput);
  } catch (const hinf::sim::SimulationError& e) {  // a run that cannot go on
    return fail(e.what(), hinf::ErrorCode::NumericalFailure);
  }
  hinf::sim::RunDirectoryReplaced replaced;
  try {
    if (o.format == "mat") add_mat_file(result);
    replaced = hinf::sim::write_campaign(result, o.out_dir, o.scenario_path, !o.no_plots);
  } catch (const hinf::Error& e) {
    return fail(e.what(), hinf::ErrorCode::InvalidInput);
  } catch (const hinf::sim::PlotError& e) {
    return fail(std::string("plots: ") + e.what(), hinf::ErrorCode::InvalidInput);
  }
  if (o.json) {
    print_run_json(result, replaced, o);
  } else if (!o.quiet) {  // the end-of-run table (docs/cli.md)
    if (replaced.previous_run) print_replaced(replaced, o.out_dir);
    for (const auto& [name, bytes] : result.files)
      if (name == "summary.json") std::cout << hinf::sim::summary_table(bytes);
    std::cout << "run directory: " << o.out_dir << "\n";
  }
  return 0;
}

}  // namespace

namespace hinf::sim_cli {

hinf::sim::StatusLog status_log(bool enabled) {
  if (!enabled) return nullptr;
  return [](const std::string& line) { std::cerr << "hinf-sim: " << line << "\n"; };
}

std::function<void(long, long)> progress_bar(bool enabled) {
  if (!enabled) return nullptr;
  if (!isatty(STDERR_FILENO))  // a log, not a terminal: a line per tenth of the runs, no \r frames
    return [](long done, long total) {
      if (done == total || (10 * done) / total != (10 * (done - 1)) / total)
        std::cerr << "hinf-sim: " << (100 * done) / total << " % of the runs (" << done << "/" << total << ")\n";
    };
  return [](long done, long total) {
    const int width = 40;
    const int filled = static_cast<int>(width * done / total);
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done << "/" << total
              << " runs" << (done == total ? "\n" : "") << std::flush;
  };
}

}  // namespace hinf::sim_cli

int main(int argc, char** argv) {
  // ulimit -f: EFBIG from the atomic writer (temporaries removed), not a kill mid-file
  std::signal(SIGXFSZ, SIG_IGN);
  hinf::remove_temporaries_on_signals();  // Ctrl-C or a kill leaves no temporary
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    // Scenario sizes are capped (kMaxSimulationSteps), so this is a machine (or ulimit -v)
    // smaller than a run of that size.
    std::cerr << "hinf-sim: error: out of memory: this machine (or its ulimit -v) cannot hold the run's "
                 "trajectories; shorten the duration or lower --runs\n";
    return kExitInvalid;
  } catch (const std::exception& e) {
    std::cerr << "hinf-sim: internal error: " << e.what() << "\n";
    return kExitNumerical;
  }
}
