// hinf-synth verify CONFIG FILE.yaml [--json]: re-derive the certificate of a gains or controller file
// at the γ it claims (synth::Problem::verify); exit 1 if it does not hold.
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/synth/api.hpp"

namespace hinf::cli {

void add_verify(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("verify", "re-derive the certificate (docs/maths.md §7, checks 2-4) of a gains file against a config, or of a controller file against a controller config");
  const auto args = add_config_gains_args(*cmd, "gains or controller YAML (must state gamma)");
  auto json = std::make_shared<bool>(false);
  auto quiet = std::make_shared<bool>(false);
  auto verbose = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "print JSON (schema hinf-synth.verify/1) instead of text");
  add_quiet_flag(*cmd, *quiet);
  add_verbose_flag(*cmd, *verbose);
  cmd->callback([=, &action] {
    action = [=]() -> int {
      const Stages stage(*verbose, "verify");
      const auto problem = stage("read " + args->config, [&] { return synth::load_problem(args->config); });
      const synth::VerifyOutcome v =
          stage("certificate of " + args->gains + " re-derived", [&] { return problem->verify(args->gains); });
      if (*json)
        print_json(v.json);
      else if (!*quiet)
        std::cout << v.report;
      return v.holds ? 0 : 1;
    };
  });
}

}  // namespace hinf::cli
