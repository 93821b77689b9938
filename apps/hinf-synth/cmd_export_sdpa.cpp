// hinf-synth export-sdpa CONFIG -o FILE.dat-s
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/controller_synthesis.hpp"
#include "hinf/synth/gains_output.hpp"

namespace hinf::cli {

void add_export_sdpa(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("export-sdpa", "write the synthesis LMI (a filter config's, or a controller config's) in SDPA sparse format (for CSDP, SDPA, ...)");
  auto config = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  cmd->add_option("config", *config, "config YAML")->required();
  cmd->add_option("-o,--output", *output, "SDPA sparse file (.dat-s) to write")->required();
  cmd->callback([=, &action] {
    action = [=]() -> int {
      const std::string bytes = synth::read_config_bytes(*config);
      if (synth::declares_controller(bytes)) {  // the controller LMI (docs/maths.md §26)
        const synth::ControllerConfig ctl = synth::parse_controller_config(bytes, *config);
        hinf::write_file_atomic(*output,
                                synth::controller_sdpa(ctl.plant, ctl.design,
                                                       std::string("from ") + *config + " (sha256 " + ctl.sha256 +
                                                           "), by hinf-synth " + synth::tool_version() +
                                                           "\nminimise the scaled gamma; the SDPA dual objective is its optimum"),
                                {*config});
        std::cout << "SDPA problem written to " << *output << "\n";
        return 0;
      }
      const synth::SynthConfig cfg = synth::parse_config(bytes, *config);
      const std::string text = synth::synthesis_sdpa(
          cfg.plant, cfg.settings, std::string("from ") + *config + " (sha256 " + cfg.sha256 +
                         "), by hinf-synth " + synth::tool_version() +
                         "\nminimise gamma^2; the SDPA dual objective is gamma*^2");
      hinf::write_file_atomic(*output, text, {*config});
      std::cout << "SDPA problem written to " << *output << "\n";
      return 0;
    };
  });
}

}  // namespace hinf::cli
