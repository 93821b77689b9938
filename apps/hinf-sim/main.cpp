// hinf-sim SCENARIO.yaml --out DIR [--runs N] [--seed S] [--jobs J]
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
#include <optional>
#include <thread>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/sim/gains_source.hpp"
#include "hinf/sim/monte_carlo.hpp"
#include "hinf/sim/plots.hpp"
#include "hinf/sim/report.hpp"
#include "hinf/sim/run_directory.hpp"
#include "hinf/sim/hold_scenario_yaml.hpp"
#include "hinf/sim/scenario_yaml.hpp"
#include "hinf/common/input_file.hpp"
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
  app.add_option("--out,-o", o.out_dir, "output directory (created if missing)")->required();
  app.add_option("--runs", o.runs, "Monte-Carlo runs (run i uses the seed derived from (seed, i))")
      ->check(CLI::Range(1L, 1000000L));
  app.add_option("--seed", o.seed, "base seed, a whole number in [0, 2^64 - 1]")->check(kWholeNumber);
  o.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--jobs,-j", o.jobs, "parallel runs (default: hardware threads)")->check(CLI::Range(1, 4096));
  app.add_option("--duration", o.duration, "override the scenario's duration (s)")->check(kFinitePositive);
  app.add_flag("--no-plots", o.no_plots, "do not run gnuplot");
  app.add_flag("--quiet,-q", o.quiet, "no progress bar");
  app.add_flag("--verbose,-v", o.verbose, "report gains origin and synthesis progress");
}

// --duration: a whole number of sample times; the steady-state window shrinks with it.
void override_duration(hinf::sim::Scenario& s, std::optional<double> duration) {
  if (!duration) return;
  s.duration = hinf::sim::checked_duration(*duration, s.sample_time);
  if (s.steady_state_start && *s.steady_state_start > s.duration) s.steady_state_start.reset();
}

// The scenario and the gains of its LTI filters (read or synthesised); the gains files
// to write beside the run's outputs (file name, content). Throws hinf::Error.
hinf::sim::RunSetup load_setup(const Options& o, hinf::sim::SummaryContext& context,
                               std::vector<std::pair<std::string, std::string>>& gains_files) {
  using namespace hinf::sim;
  RunSetup setup;
  setup.scenario = load_scenario(o.scenario_path);
  Scenario& s = setup.scenario;
  override_duration(s, o.duration);
  for (const char* name : {"hinf", "published"}) {
    const bool hinf = std::string(name) == "hinf";
    const auto& src = hinf ? s.filters.hinf : s.filters.published;
    if (!src) continue;
    ObtainedGains g;
    try {
      g = obtain_gains(*src, hinf::sim_cli::status_log(o.verbose));
    } catch (const hinf::Error& e) {  // name a synthesis as such; a gains file names itself
      if (src->synthesize_path.empty()) throw;
      throw hinf::Error(e.code(), std::string("synthesis: ") + e.what());
    }
    // The sim feeds y = Cartesian position (m = 3) and reads the whole state (l = 6).
    if (g.gains.B_F.cols() != 3 || g.gains.C_F.rows() != 6)
      throw hinf::Error(hinf::ErrorCode::InvalidInput,
                        "filters." + std::string(name) + ": " + g.origin + ": B_F has " +
                            std::to_string(g.gains.B_F.cols()) + " columns and C_F " +
                            std::to_string(g.gains.C_F.rows()) +
                            " rows; hinf-sim needs m = 3 (Cartesian position measured) and l = 6 (L = I6)");
    if (o.verbose) std::cerr << "hinf-sim: " << name << ": " << g.origin << "\n";
    (hinf ? setup.hinf : setup.published) = g.gains;
    context.gains[name] = {g.origin, g.gamma};
    gains_files.emplace_back(hinf ? "gains.yaml" : "published_gains.yaml", g.gains_yaml);
  }
  return setup;
}

// The run's files, written together (hinf::sim::write_run_directory), never over the gains
// files or synthesis configs the scenario names. Throws hinf::Error or PlotError.
void write_outputs(const Options& o, const hinf::sim::RunSetup& setup, const std::vector<hinf::sim::RunResult>& results,
                   const hinf::sim::SummaryContext& context,
                   const std::vector<std::pair<std::string, std::string>>& gains_files) {
  using namespace hinf::sim;
  const Trajectory& trajectory = *results.front().trajectory;
  std::vector<std::pair<std::string, std::string>> files{{"trajectory.csv", format_trajectory_csv(trajectory)}};
  files.insert(files.end(), gains_files.begin(), gains_files.end());
  files.push_back({"runs.csv", format_runs_csv(results)});
  files.push_back({"summary.json", format_summary_json(setup.scenario, results, context)});
  std::vector<std::string> inputs;
  for (const auto& src : {setup.scenario.filters.hinf, setup.scenario.filters.published})
    if (src) inputs.push_back(src->gains_path.empty() ? src->synthesize_path : src->gains_path);
  hinf::sim_cli::write_run_directory(o, files, inputs, setup.scenario.plots,
                                     [&](const std::string& title, hinf::AtomicFileSet& outputs) {
                                       write_plots(o.out_dir, trajectory, title, outputs);
                                     });
}

int run(int argc, char** argv) {
  CLI::App app{"hinf-sim: nonlinear relative-navigation experiments comparing the H∞ filter, the paper's "
               "published gains, EKFs and the REKF (docs/experiments.md)"};
  Options o;
  add_options(app, o);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : kExitInvalid;
  }

  using namespace hinf::sim;
  try {  // the scenario family: `scenario: tumbling_hold`, `gps_ins_relative`, `gyroless_attitude`, `manoeuvring_target`, or the Hill experiments
    const std::string text = hinf::read_input_file(o.scenario_path, "scenario", hinf::kMaxScenarioBytes);
    const std::string family = scenario_family(text, o.scenario_path);
    if (family == "tumbling_hold") return hinf::sim_cli::run_tumbling_hold(o, text);
    if (family == "gps_ins_relative") return hinf::sim_cli::run_gps_ins(o, text);
    if (family == "gyroless_attitude") return hinf::sim_cli::run_gyroless_attitude(o, text);
    if (family == "manoeuvring_target") return hinf::sim_cli::run_manoeuvring_target(o, text);
  } catch (const hinf::Error& e) {
    std::cerr << "hinf-sim: error: " << e.what() << "\n";
    return hinf::exit_code(e.code());
  }
  SummaryContext context;
  context.scenario_path = o.scenario_path;
  context.seed = o.seed;
  std::vector<std::pair<std::string, std::string>> gains_files;  // file name, content
  RunSetup setup;
  try {
    setup = load_setup(o, context, gains_files);
  } catch (const hinf::Error& e) {  // scenario, gains file, synthesis config or synthesis
    std::cerr << "hinf-sim: error: " << e.what() << "\n";
    return hinf::exit_code(e.code());
  }

  std::vector<RunResult> results;
  try {
    results = run_monte_carlo(setup, o.runs, o.seed, o.jobs, hinf::sim_cli::progress_bar(!o.quiet && o.runs > 1));
  } catch (const std::invalid_argument& e) {  // runtime filters refusing their gains/settings
    std::cerr << "hinf-sim: error: " << e.what() << "\n";
    return kExitInvalid;
  } catch (const SimulationError& e) {
    std::cerr << "hinf-sim: error: " << e.what() << "\n";
    return kExitNumerical;
  }

  try {
    write_outputs(o, setup, results, context, gains_files);
  } catch (const hinf::Error& e) {
    std::cerr << "hinf-sim: error: " << e.what() << "\n";
    return kExitInvalid;
  } catch (const PlotError& e) {
    std::cerr << "hinf-sim: error: plots: " << e.what() << "\n";
    return kExitInvalid;
  }
  return 0;
}

}  // namespace

namespace hinf::sim_cli {

void write_run_directory(const Options& o, const std::vector<std::pair<std::string, std::string>>& files,
                         const std::vector<std::string>& inputs, bool plots_enabled,
                         const std::function<void(const std::string& title, hinf::AtomicFileSet& outputs)>& plots) {
  std::vector<std::string> read = inputs;
  read.push_back(o.scenario_path);
  const std::string title = std::filesystem::path(o.scenario_path).stem().string();
  hinf::sim::write_run_directory(o.out_dir, files, read,
                                 o.no_plots || !plots_enabled
                                     ? std::function<void(hinf::AtomicFileSet&)>()
                                     : [&](hinf::AtomicFileSet& outputs) { plots(title, outputs); });
}

int run_stages(const std::function<void()>& load, const std::function<void()>& simulate,
               const std::function<void()>& write) {
  const auto fail = [](const std::string& what, hinf::ErrorCode code) {
    std::cerr << "hinf-sim: error: " << what << "\n";
    return hinf::exit_code(code);
  };
  try {
    load();
  } catch (const hinf::Error& e) {
    return fail(e.what(), e.code());
  }
  try {
    simulate();
  } catch (const hinf::Error& e) {  // a scenario value a filter refuses, named by its key
    return fail(e.what(), e.code());
  } catch (const std::invalid_argument& e) {
    return fail(e.what(), hinf::ErrorCode::InvalidInput);
  } catch (const hinf::sim::SimulationError& e) {
    return fail(e.what(), hinf::ErrorCode::NumericalFailure);
  }
  try {
    write();
  } catch (const hinf::Error& e) {
    return fail(e.what(), hinf::ErrorCode::InvalidInput);
  } catch (const hinf::sim::PlotError& e) {
    return fail(std::string("plots: ") + e.what(), hinf::ErrorCode::InvalidInput);
  }
  return 0;
}

hinf::sim::StatusLog status_log(bool enabled) {
  if (!enabled) return nullptr;
  return [](const std::string& line) { std::cerr << "hinf-sim: " << line << "\n"; };
}

std::function<void(long, long)> progress_bar(bool enabled) {
  if (!enabled) return nullptr;
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
