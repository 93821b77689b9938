// Obtaining an LTI filter's gains for a scenario: read a gains file
// (hinf::runtime_yaml::load_gains_file) or synthesise them now from a synthesis config
// (hinf::synth::load_config + synthesize, SPEC §2).
#pragma once
#include <optional>
#include <string>

#include "hinf/sim/run.hpp"
#include "hinf/sim/scenario.hpp"

namespace hinf::sim {

struct ObtainedGains {
  LtiGains gains;
  std::optional<double> gamma;  // the certified bound, if known
  std::string gains_yaml;       // the gains in the gains-file schema (file bytes, or generated)
  std::string origin;           // "gains file PATH" or "synthesised from PATH"
};

// Errors propagate as hinf::runtime_yaml::GainsFileError (invalid file: exit 2) or
// hinf::synth::Error (its own code: invalid 2, infeasible 3, numerical 4).
ObtainedGains obtain_gains(const LtiGainsSource& source, bool verbose);

// The gains-file schema (docs/file-formats.md), doubles with 17 significant digits.
std::string format_gains_yaml(const LtiGains& gains, std::optional<double> gamma, const std::string& tool,
                              const std::string& config_sha256);

}  // namespace hinf::sim
