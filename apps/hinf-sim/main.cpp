// hinf-sim SCENARIO.yaml --out DIR [--runs N] [--seed S] [--jobs J]
// Exit codes: 0 ok, 2 invalid input or unwritable output, 3 infeasible synthesis,
// 4 numerical failure (synthesis certificate, non-finite truth).
#include <CLI/CLI.hpp>
#include <hinf/common/error.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <thread>

#include "hinf/common/atomic_file.hpp"
#include "hinf/sim/gains_source.hpp"
#include "hinf/sim/monte_carlo.hpp"
#include "hinf/sim/plots.hpp"
#include "hinf/sim/report.hpp"
#include "hinf/sim/scenario_yaml.hpp"

namespace {

constexpr int kExitInvalid = 2;
constexpr int kExitNumerical = 4;

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled) {}
  void operator()(long done, long total) const {
    if (!enabled_) return;
    const int width = 40;
    const int filled = static_cast<int>(width * done / total);
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done << "/" << total
              << " runs" << (done == total ? "\n" : "") << std::flush;
  }

 private:
  bool enabled_;
};

int run(int argc, char** argv) {
  CLI::App app{"hinf-sim: nonlinear relative-navigation experiments comparing the H∞ filter, the paper's "
               "published gains, EKFs and the REKF (docs/experiments.md)"};
  std::string scenario_path, out_dir;
  long runs = 1;
  std::uint64_t seed = 1;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  double duration = -1;
  bool no_plots = false, quiet = false, verbose = false;
  app.add_option("scenario", scenario_path, "scenario file (YAML)")->required();
  app.add_option("--out,-o", out_dir, "output directory (created if missing)")->required();
  app.add_option("--runs", runs, "Monte-Carlo runs (run i uses the seed derived from (seed, i))")
      ->check(CLI::Range(1L, 1000000L));
  app.add_option("--seed", seed, "base seed");
  app.add_option("--jobs,-j", jobs, "parallel runs (default: hardware threads)")->check(CLI::Range(1, 4096));
  app.add_option("--duration", duration, "override the scenario's duration (s)")->check(CLI::PositiveNumber);
  app.add_flag("--no-plots", no_plots, "do not run gnuplot");
  app.add_flag("--quiet,-q", quiet, "no progress bar");
  app.add_flag("--verbose,-v", verbose, "report gains origin and synthesis progress");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : kExitInvalid;
  }

  using namespace hinf::sim;
  RunSetup setup;
  SummaryContext context;
  context.scenario_path = scenario_path;
  context.seed = seed;
  std::vector<std::pair<std::string, std::string>> gains_files;  // file name, content
  try {
    setup.scenario = load_scenario(scenario_path);
    Scenario& s = setup.scenario;
    if (duration > 0) {
      const double ratio = duration / s.sample_time;
      if (std::fabs(ratio - std::round(ratio)) > 1e-6 * std::max(1.0, ratio))
        throw hinf::Error(hinf::ErrorCode::InvalidInput,
                          "--duration " + std::to_string(duration) + ": must be a whole number of sample times");
      s.duration = duration;
      if (s.steady_state_start && *s.steady_state_start > duration) s.steady_state_start.reset();
    }
    for (const char* name : {"hinf", "published"}) {
      const auto& src = std::string(name) == "hinf" ? s.filters.hinf : s.filters.published;
      if (!src) continue;
      ObtainedGains g;
      try {
        g = obtain_gains(*src, verbose);
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
      if (verbose) std::cerr << "hinf-sim: " << name << ": " << g.origin << "\n";
      (std::string(name) == "hinf" ? setup.hinf : setup.published) = g.gains;
      context.gains[name] = {g.origin, g.gamma};
      gains_files.emplace_back(std::string(name) == "hinf" ? "gains.yaml" : "published_gains.yaml", g.gains_yaml);
    }
  } catch (const hinf::Error& e) {  // scenario, gains file, synthesis config or synthesis
    std::cerr << "hinf-sim: error: " << e.what() << "\n";
    return hinf::exit_code(e.code());
  }

  std::vector<RunResult> results;
  try {
    results = run_monte_carlo(setup, runs, seed, jobs, ProgressBar(!quiet && runs > 1));
  } catch (const std::invalid_argument& e) {  // runtime filters refusing their gains/settings
    std::cerr << "hinf-sim: error: " << e.what() << "\n";
    return kExitInvalid;
  } catch (const SimulationError& e) {
    std::cerr << "hinf-sim: error: " << e.what() << "\n";
    return kExitNumerical;
  }

  try {
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec || !std::filesystem::is_directory(out_dir))
      throw hinf::Error(hinf::ErrorCode::InvalidInput,
                        "cannot create the output directory '" + out_dir + "': " + ec.message());
    namespace fs = std::filesystem;
    const Trajectory& trajectory = *results.front().trajectory;
    // One set: the run's files appear together or not at all.
    hinf::AtomicFileSet outputs;
    outputs.add((fs::path(out_dir) / "trajectory.csv").string(), format_trajectory_csv(trajectory));
    for (const auto& [file, content] : gains_files) outputs.add((fs::path(out_dir) / file).string(), content);
    outputs.add((fs::path(out_dir) / "runs.csv").string(), format_runs_csv(results));
    outputs.add((fs::path(out_dir) / "summary.json").string(), format_summary_json(setup.scenario, results, context));
    if (!no_plots && setup.scenario.plots)
      write_plots(out_dir, trajectory, fs::path(scenario_path).stem().string(), outputs);
    outputs.commit();
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

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "hinf-sim: internal error: " << e.what() << "\n";
    return kExitNumerical;
  }
}
