// hinf-synth export-sdpa CONFIG -o FILE.dat-s [--json]: the synthesis LMI of any problem kind
// (synth::Problem::export_sdpa) in SDPA sparse format.
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/synth/api.hpp"

namespace hinf::cli {

void add_export_sdpa(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("export-sdpa", "write the synthesis LMI (a filter config's, or a controller config's) in SDPA sparse format (for CSDP, SDPA, ...)");
  auto config = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto quiet = std::make_shared<bool>(false);
  auto verbose = std::make_shared<bool>(false);
  cmd->add_option("config", *config, "config YAML")->required();
  cmd->add_option("-o,--output", *output, "SDPA sparse file (.dat-s) to write (- for stdout)")->required();
  add_quiet_flag(*cmd, *quiet);
  add_verbose_flag(*cmd, *verbose);
  cmd->add_flag("--json", *json, "print JSON (schema hinf-synth.export-sdpa/1: what was written) instead of text");
  cmd->callback([=, &action] {
    action = [=]() -> int {
      require_one_use_of_stdout(*output, *json);
      const Stages stage(*verbose, "export-sdpa");
      const std::unique_ptr<synth::Problem> problem =
          stage("read " + *config, [&] { return synth::load_problem(*config); });
      const std::string sdpa = stage("LMI written in SDPA form", [&] { return problem->export_sdpa(); });
      stage("wrote " + *output, [&] { write_output(*output, sdpa, {*config}); });
      if (*json) {
        Json j;
        j["schema"] = synth::json_schema("export-sdpa");
        j["kind"] = std::string(problem->kind());
        j["config"] = *config;
        j["output"] = *output;
        j["bytes"] = sdpa.size();
        print_json(j);
      } else if (!*quiet) {
        report_stream(*output) << "SDPA problem written to " << (*output == "-" ? std::string("stdout") : *output) << "\n";
      }
      return 0;
    };
  });
}

}  // namespace hinf::cli
