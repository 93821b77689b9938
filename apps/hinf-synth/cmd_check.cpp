// hinf-synth check CONFIG --golden GOLDEN.yaml [--rtol R] [--json]: regression of the synthesis
// (synth::Problem::check). The designs are compared as transfer functions (docs/maths.md
// (61), [D14]): another state-space realisation of the same filter or controller passes; a
// real change fails. Because the optimum is not unique, a golden design whose transfer
// function differs is still accepted when it remains certified for the config at the golden
// γ (within min(rtol, 1e-6)): an equally optimal design.
#include <iostream>
#include <memory>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/synth/api.hpp"

namespace hinf::cli {

void add_check(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("check", "re-synthesise and compare with a golden gains or controller file (exit 0 same, 1 changed)");
  auto config = std::make_shared<std::string>();
  auto golden = std::make_shared<std::string>();
  auto rtol = std::make_shared<double>(1e-6);
  auto json = std::make_shared<bool>(false);
  auto quiet = std::make_shared<bool>(false);
  auto verbose = std::make_shared<bool>(false);
  cmd->add_option("config", *config, "config YAML")->required();
  cmd->add_option("--golden", *golden, "golden gains or controller YAML")->required();
  cmd->add_option("--rtol", *rtol, "relative tolerance on gamma and on the designs' transfer-function difference")
      ->check(CLI::Range(1e-14, 1.0));
  cmd->add_flag("--json", *json, "print JSON (schema hinf-synth.check/1) instead of text");
  add_quiet_flag(*cmd, *quiet);
  add_verbose_flag(*cmd, *verbose, "the re-synthesis's iteration table on stderr");
  cmd->callback([=, &action] {
    action = [=]() -> int {
      const std::unique_ptr<synth::Problem> problem = synth::load_problem(*config);
      std::optional<VerboseLog> log;
      const synth::CheckOutcome c =
          problem->check(*golden, *rtol, verbose_observers(*verbose || problem->verbose(), log));
      if (*json)
        print_json(c.json);
      else if (!*quiet)
        std::cout << c.report;
      return c.same ? 0 : 1;
    };
  });
}

}  // namespace hinf::cli
