// hinf-synth solve CONFIG -o FILE.yaml [--verbose] [--json]: the certified design of any problem kind
// (synth::Problem::solve), its file written atomically, its report printed.
#include <cstdio>
#include <iostream>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/synth/api.hpp"

namespace hinf::cli {

void add_solve(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("solve", "synthesise a certified robust H-infinity filter (Theorem 1, or the observer form for plants that are not Schur stable) or output-feedback controller");
  auto config = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto verbose = std::make_shared<bool>(false);
  auto json = std::make_shared<bool>(false);
  cmd->add_option("config", *config, "config YAML (system matrices, hill model, or controller)")->required();
  cmd->add_option("-o,--output", *output, "gains or controller YAML to write (atomically; - for stdout)")->required();
  add_verbose_flag(*cmd, *verbose, "coefficient ranges and the solver's iteration table on stderr");
  cmd->add_flag("--json", *json, "print JSON (schema hinf-synth.solve/1: gamma and the written file's contents) instead of text");
  auto format = std::make_shared<std::string>();
  add_format_option(*cmd, *format);
  auto quiet = std::make_shared<bool>(false);
  add_quiet_flag(*cmd, *quiet);
  cmd->callback([=, &action] {
    action = [=]() -> int {
      require_one_use_of_stdout(*output, *json);
      const std::unique_ptr<synth::Problem> problem = synth::load_problem(*config);
      std::optional<VerboseLog> log;
      const synth::SolveOutcome r = problem->solve(verbose_observers(*verbose || problem->verbose(), log));
      deliver_solved(r, *output, *format, *config, *json, *quiet);
      return 0;
    };
  });
}

}  // namespace hinf::cli
