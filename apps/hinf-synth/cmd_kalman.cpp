// hinf-synth kalman CONFIG -o GAINS.yaml [--json]: the Kalman predictor of the config's plant (or, with
// filter.estimate: filtered, the Kalman filter x̂(k|k), docs/maths.md (143)).
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/synth/api.hpp"

namespace hinf::cli {

void add_kalman(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "kalman", "the Kalman one-step predictor of the config's nominal plant (Q = B B^T, R = D D^T, or the config's kalman: {Q, R}), certified at the "
                "worst-case gain it achieves: the H2 reference for the H-infinity filter (filter.estimate: filtered: the Kalman filter x_hat(k|k))");
  auto config = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("config", *config, "config YAML (system matrices or hill model)")->required();
  cmd->add_option("-o,--output", *output, "gains YAML to write (atomically; - for stdout)")->required();
  cmd->add_flag("--json", *json, "print JSON (schema hinf-synth.kalman/1: gamma and the written file's contents) instead of text");
  auto format = std::make_shared<std::string>();
  add_format_option(*cmd, *format);
  auto quiet = std::make_shared<bool>(false);
  add_quiet_flag(*cmd, *quiet);
  auto verbose = std::make_shared<bool>(false);
  add_verbose_flag(*cmd, *verbose);
  cmd->callback([=, &action] {
    action = [=]() -> int {
      require_one_use_of_stdout(*output, *json);
      const Stages stage(*verbose, "kalman");
      const auto problem = stage("read " + *config, [&] { return synth::load_problem(*config); });
      const synth::SolveOutcome r = stage("Kalman gains computed and certified", [&] { return problem->kalman(); });
      deliver_solved(r, *output, *format, *config, *json, *quiet);
      return 0;
    };
  });
}

}  // namespace hinf::cli
