// hinf-synth solve CONFIG -o GAINS.yaml [--verbose]
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/sdp/time_model.hpp"
#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/controller_output.hpp"
#include "hinf/synth/gains_output.hpp"

namespace hinf::cli {

namespace {

// `solve` of a `controller:` config (docs/maths.md §26): the controller file.
int solve_controller(const synth::ControllerConfig& cfg, const std::string& output, bool verbose) {
  std::optional<VerboseLog> log;
  if (verbose || cfg.settings.verbose) log.emplace(stderr);
  const synth::ControllerSynthesisResult r =
      log ? synth::synthesize_controller(cfg.plant, cfg.settings, cfg.design, IterationTable(*log))
          : synth::synthesize_controller(cfg.plant, cfg.settings, cfg.design);
  const std::optional<double> period =
      cfg.plant.time == TimeDomain::Discrete ? std::optional<double>(cfg.plant.sample_time) : std::nullopt;
  hinf::write_file_atomic(output, synth::format_controller_yaml(r, cfg.plant, cfg.design, {cfg.path, cfg.sha256, period}),
                          {cfg.path});
  std::cout << "gamma = " << num(r.gamma) << " (closed-loop Hinf norm " << num(r.certificate.closed_loop_hinf_norm)
            << "), certified; " << (cfg.design.strictly_proper ? "strictly proper " : "") << to_string(cfg.plant.time)
            << "-time controller written to " << output << " [" << r.newton_iterations << " Newton iterations, "
            << num(r.time_s) << " s]\n"
            << "cond(N) = " << num(r.certificate.cond_N) << "; gamma bounds the gain from w to z of the closed loop\n";
  if (r.gamma_optimal)
    std::cout << "gamma back-off" << (cfg.settings.gamma_backoff > 0 ? "" : " (automatic: I - R S is singular at the optimum)")
              << ": the LMI's optimum is " << num(*r.gamma_optimal) << "; the controller is recovered at (1 + "
              << num(r.backoff) << ") times it, at the point of largest LMI margin (docs/maths.md (149a))\n";
  if (r.gamma_without_disk && !r.robust_synthesis)
    std::cout << "pole disk: without it the LMI's optimum is " << num(*r.gamma_without_disk) << " (+"
              << num(100 * (r.gamma / *r.gamma_without_disk - 1)) << " % for the disk)\n";
  if (r.robust_synthesis)
    std::cout << "robust synthesis (docs/maths.md (160a)): the H-infinity-optimal controller had ‖T_qp‖∞ = "
              << num(*r.nominal_robust_channel_norm) << " >= 1; this one is designed for ‖T_qp‖∞ < 1 (D-scaling d = "
              << num(r.robust_scaling) << "; the least ‖T_qp‖∞ of any controller is about "
              << num(*r.least_robust_channel_norm) << ")\n";
  if (r.certificate.robust_channel_norm)
    std::cout << "robust channel: ‖T_qp‖∞ = " << num(*r.certificate.robust_channel_norm)
              << " < 1: stable for every perturbation H F E with ‖F‖ <= 1 (small gain)\n";
  return 0;
}

}  // namespace

void add_solve(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("solve", "synthesise a certified robust H-infinity filter (Theorem 1, or the observer form for plants that are not Schur stable)");
  auto config = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto verbose = std::make_shared<bool>(false);
  cmd->add_option("config", *config, "config YAML (system matrices or hill model)")->required();
  cmd->add_option("-o,--output", *output, "gains YAML to write (atomically)")->required();
  cmd->add_flag("-v,--verbose", *verbose, "coefficient ranges and the solver's iteration table on stderr");
  cmd->callback([=, &action] {
    action = [=]() -> int {
      const std::string bytes = synth::read_config_bytes(*config);
      if (synth::declares_controller(bytes)) return solve_controller(synth::parse_controller_config(bytes, *config), *output, *verbose);
      synth::SynthConfig cfg = synth::parse_config(bytes, *config);
      const bool v = *verbose || cfg.settings.verbose;
      std::optional<VerboseLog> log;
      if (v) {
        print_coefficient_ranges(cfg.plant, stderr);
        log.emplace(stderr);
        const synth::ProblemSize size = synth::problem_size(cfg.plant, cfg.settings);
        log->line("%s form: LMI order %d, %d variables; solver memory estimate %.0f MiB (limit max_memory_mb = %.0f)",
                  to_string(size.form), size.lmi_order, size.variables, std::ceil(size.memory_mib),
                  cfg.settings.max_memory_mb);
        log->line("time estimate (docs/benchmarks.md \"Time\"): %s per Newton iteration, %s to %s for %d-%d of them, "
                  "on a machine like the development one", seconds_text(size.newton_iteration_s).c_str(),
                  seconds_text(size.fewest_s).c_str(), seconds_text(size.most_s).c_str(),
                  sdp::kFewestNewtonIterations, sdp::kMostNewtonIterations);
      }
      const synth::SynthesisResult r =
          v ? synth::synthesize(cfg.plant, cfg.settings, IterationTable(*log))
            : synth::synthesize(cfg.plant, cfg.settings);
      if (v) {
        log->line("LMI order %d, %d variables; scaling applied (powers of two, exact): %s", r.solver.lmi_order,
                  r.solver.variables, r.solver.scaling.c_str());
        if (r.solver.gap_certified)
          log->line("optimality gap certified by a dual point: gamma*^2 in [%.10g, %.10g]",
                    r.solver.dual_bound_gamma_squared, r.solver.optimal_gamma * r.solver.optimal_gamma);
        else
          log->line("optimality gap not certified: %s", r.solver.gap_detail.c_str());
      }
      hinf::write_file_atomic(*output, synth::format_gains_yaml(r, {*config, cfg.sha256, cfg.sample_time()}), {*config});
      std::cout << "gamma = " << num(r.gamma) << " (nominal Hinf norm " << num(r.certificate.hinf_norm_nominal)
                << ", robust bound " << num(r.certificate.robust_bound) << "), certified; gains written to "
                << *output << " [" << r.solver.newton_iterations << " Newton iterations, "
                << num(r.solver.time_s) << " s]\n"
                << "RMS error under unit white noise (H2 norm) " << num(r.certificate.h2_norm_nominal)
                << " (compare: hinf-synth kalman)\n"
                << "filter form: " << to_string(r.filter.form) << (r.filter.filtered() ? ", filtered estimate" : "")
                << "; " << r.bound << "\n";
      return 0;
    };
  });
}

}  // namespace hinf::cli
