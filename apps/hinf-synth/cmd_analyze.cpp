// hinf-synth analyze CONFIG FILE.yaml [--json]: the figures of a gains or controller file on
// the config's problem (synth::Problem::analyze).
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/synth/api.hpp"

namespace hinf::cli {

void add_analyze(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("analyze", "nominal Hinf norm, robust bound, the worst case found over the uncertainty (and the delta grid of hill configs) of any filter; the closed loop of any controller");
  const auto args = add_config_gains_args(*cmd, "gains or controller YAML");
  auto json = std::make_shared<bool>(false);
  auto quiet = std::make_shared<bool>(false);
  auto verbose = std::make_shared<bool>(false);
  auto points = std::make_shared<int>(41);
  cmd->add_flag("--json", *json, "print JSON (schema hinf-synth.analyze/1) instead of text");
  add_quiet_flag(*cmd, *quiet);
  add_verbose_flag(*cmd, *verbose);
  cmd->add_option("--delta-points", *points, "grid points over [-delta_bar, delta_bar] (hill configs)")
      ->check(CLI::Range(2, 100001));
  cmd->callback([=, &action] {
    action = [=]() -> int {
      const Stages stage(*verbose, "analyze");
      const auto problem = stage("read " + args->config, [&] { return synth::load_problem(args->config); });
      const synth::AnalysisOutcome a =
          stage("analysed " + args->gains, [&] { return problem->analyze(args->gains, {*points}); });
      if (*json)
        print_json(a.json);
      else if (!*quiet)
        std::cout << a.report;
      return 0;
    };
  });
}

}  // namespace hinf::cli
