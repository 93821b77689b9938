#include "cli_support.hpp"

#include <filesystem>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/gnuplot.hpp"

#include "hinf/common/number_text.hpp"
#include "hinf/matfile/mat_file.hpp"
#include "hinf/sdp/time_model.hpp"

#include <cmath>
#include <iostream>
#include <utility>

namespace hinf::cli {

using hinf::Error;
using hinf::ErrorCode;

std::shared_ptr<ConfigGainsArgs> add_config_gains_args(CLI::App& cmd, const std::string& gains_help) {
  auto args = std::make_shared<ConfigGainsArgs>();
  cmd.add_option("config", args->config, "config YAML")->required();
  cmd.add_option("gains", args->gains, gains_help)->required();
  return args;
}

std::string num(double v) { return hinf::significant_text(v, 10); }

void write_output(const std::string& path, const std::string& bytes, const std::vector<std::string>& inputs) {
  if (path == "-") {
    std::cout.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    std::cout.flush();
    if (!std::cout) throw Error(ErrorCode::InvalidInput, "cannot write to stdout");
    return;
  }
  write_file_atomic(path, bytes, inputs);
}

std::ostream& report_stream(const std::string& output) { return output == "-" ? std::cerr : std::cout; }

void require_one_use_of_stdout(const std::string& output, bool json) {
  if (output == "-" && json)
    throw Error(ErrorCode::InvalidInput, "-o - and --json both write to stdout: give -o a file, or drop --json",
                "--json");
}

void add_quiet_flag(CLI::App& cmd, bool& quiet) {
  cmd.add_flag("-q,--quiet", quiet, "no report on success (errors and --json are still printed)");
}

void Stages::line(const std::string& text) const {
  if (enabled_) std::cerr << "hinf-synth: " << subcommand_ << ": " << text << std::endl;
}

void Stages::log(const std::string& stage, std::chrono::steady_clock::time_point start) const {
  if (!enabled_) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  line(stage + " (" + significant_text(s, 3) + " s)");
}

void add_verbose_flag(CLI::App& cmd, bool& verbose, const std::string& what) {
  cmd.add_flag("-v,--verbose", verbose, what);
}

synth::JobObservers verbose_observers(bool enabled, std::optional<VerboseLog>& log) {
  synth::JobObservers observers;
  if (!enabled) return observers;
  log.emplace(stderr);
  observers.on_iteration = IterationTable(*log);
  observers.on_log = [&log](const std::string& line) { log->line("%s", line.c_str()); };
  return observers;
}

void add_format_option(CLI::App& cmd, std::string& format) {
  cmd.add_option("--format", format, "file format: yaml or mat (MATLAB; default: mat if the output ends in .mat)")
      ->check(CLI::IsMember({"yaml", "mat"}));
}

std::string file_bytes(const synth::SolveOutcome& r, const std::string& format, const std::string& output) {
  const bool mat = format == "mat" || (format.empty() && output.size() > 4 && output.substr(output.size() - 4) == ".mat");
  if (!mat) return r.file;
  const Json file = Json::parse(r.json)["file"];  // the file's keys and values (synth/api.hpp)
  return matfile::mat_file_bytes(file, "MATLAB 5.0 MAT-file, " + file["format"].get<std::string>() + " written by " +
                                           file["tool"].get<std::string>());
}

void deliver_solved(const synth::SolveOutcome& r, const std::string& output, const std::string& format,
                    const std::string& config, bool json, bool quiet) {
  write_output(output, file_bytes(r, format, output), {config});
  if (json)
    print_json(r.json, {{"output", output}});
  else if (!quiet)
    report_stream(output) << r.report << r.file_contents << " written to "
                          << (output == "-" ? std::string("stdout") : output) << "\n";
}

void print_json(const Json& j) { std::cout << j.dump(-1, ' ', false, Json::error_handler_t::replace) << "\n"; }

void print_json(const std::string& json_line, const std::vector<std::pair<std::string, std::string>>& paths) {
  Json j = Json::parse(json_line);
  for (const auto& [key, path] : paths) j[key] = path;
  print_json(j);
}

bool IterationTable::heartbeat(const sdp::Progress& r) {
  if (r.newton_step && !estimated_ && r.centering == 0 && r.newton == 1) {  // the first Newton iteration has ended
    estimated_ = true;
    if (r.elapsed_s >= kEstimateAfterSeconds)
      log_->line("first Newton iteration took %.1f s; the solves measured in docs/benchmarks.md took %d-%d Newton "
                 "iterations, so expect roughly %.0f-%.0f s for this solve (more for the back-off and the bracket)",
                 r.elapsed_s, sdp::kFewestNewtonIterations, sdp::kMostNewtonIterations,
                 sdp::kFewestNewtonIterations * r.elapsed_s, sdp::kMostNewtonIterations * r.elapsed_s);
  }
  if (!r.assembling) return false;
  if (r.elapsed_s - last_line_s_ >= kQuietSeconds) {
    log_->line("%5d        %10.3e  (assembling the Newton system, %.1f s)", r.phase, r.t, r.elapsed_s);
    last_line_s_ = r.elapsed_s;
  }
  return true;
}

void IterationTable::operator()(const synth::IterationReport& report) {
  using synth::SolveStage;
  const sdp::Progress& r = report.progress;
  log_->set_activity("phase " + std::to_string(r.phase) + ", centring " + std::to_string(r.centering) +
                     (r.newton_step ? ", Newton iteration " + std::to_string(r.newton) : std::string()));
  if (heartbeat(r)) return;
  if (r.newton_step && r.elapsed_s - last_line_s_ < kQuietSeconds) return;  // only on large problems
  if (!started_ || report.stage != stage_) {
    if (report.stage == SolveStage::Backoff)
      log_->line("==== gamma back-off: maximise the LMI margin at (1+b) gamma* ====");
    log_->line("phase  step  %10s  %16s  %10s  newton  %9s  time[s]", "t", "objective", "gap", "lambda^2");
    started_ = true;
    stage_ = report.stage;
    last_phase_ = 0;
  }
  if (r.phase == 2 && last_phase_ != 2)
    log_->line("---- phase 2: minimise %s ----", report.stage == SolveStage::Backoff      ? "-margin"
                                                 : report.stage == SolveStage::Controller ? "gamma (equilibrated plant)"
                                                                                          : "gamma^2");
  last_phase_ = r.phase;
  last_line_s_ = r.elapsed_s;
  if (r.newton_step)
    log_->line("%5d  %4d  %10.3e  %16s  %10s  %6d  %9.2e  %7.3f  (newton iteration in progress)", r.phase,
               r.centering, r.t, "", "", r.newton, r.lambda2, r.elapsed_s);
  else
    log_->line("%5d  %4d  %10.3e  %16.10e  %10.3e  %6d  %9.2e  %7.3f", r.phase, r.centering, r.t, r.objective,
               r.gap, r.newton, r.lambda2, r.elapsed_s);
}

void write_png_by_gnuplot(const std::string& png, const std::string& csv,
                          const std::function<std::string(const std::string&, const std::string&)>& script,
                          const std::vector<std::string>& inputs) {
  AtomicFileSet outputs;
  for (const auto& in : inputs) outputs.protect(in);
  const std::string png_tmp = outputs.reserve(png);
  AtomicFileSet scratch;  // never committed: removed on return
  const std::filesystem::path dir = std::filesystem::path(png).parent_path();
  const auto beside = [&](const std::string& f) { return ((dir.empty() ? std::filesystem::path(".") : dir) / f).string(); };
  const std::string data = scratch.add(beside("plot-data.csv"), csv);
  const std::string gp = scratch.add(beside("plot-script.gp"), script(data, png_tmp));
  const int rc = run_gnuplot(gp);
  std::error_code ec;
  if (rc != 0 || !std::filesystem::exists(png_tmp, ec) || std::filesystem::file_size(png_tmp, ec) == 0)
    throw Error(ErrorCode::InvalidInput, rc < 0 ? "--plot: cannot run gnuplot (is the gnuplot package installed?)"
                                                : "--plot: gnuplot failed (exit status " + std::to_string(rc) + ")");
  outputs.commit();
}

}  // namespace hinf::cli
