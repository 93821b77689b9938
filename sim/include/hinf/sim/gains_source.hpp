// Obtaining an LTI filter's gains for a scenario: read a gains file
// (hinf::runtime_yaml::load_gains_file) or synthesise them now from a synthesis config
// (hinf::synth::load_config + synthesize, docs/maths.md §3–§7).
#pragma once
#include <optional>
#include <string>

#include "hinf/sim/run.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/sim/scenario.hpp"
#include "hinf/sim/status_log.hpp"

namespace hinf::sim {

struct ObtainedGains {
  LtiGains gains;
  std::optional<double> gamma;  // the certified bound, if known
  std::string gains_yaml;       // the gains file: its bytes, or the synthesis library's gains writer
                                // (hinf::synth::format_gains_yaml) for synthesised gains
  std::string origin;           // "gains file PATH" or "synthesised from PATH"
};

// A filter with a known input (G_F) is refused where the scenario feeds it y only; where the
// scenario's known input is zero (linear_plant), G_F multiplies zero and is dropped.
enum class KnownInput { Refused, Zero };

// Errors propagate as hinf::Error with its own code: an invalid gains file or config is
// InvalidInput (exit 2); a synthesis may also end Infeasible (3) or NumericalFailure (4).
// `log` (may be empty) hears that a synthesis starts.
ObtainedGains obtain_gains(const LtiGainsSource& source, const StatusLog& log,
                           KnownInput known_input = KnownInput::Refused);

// The gains of a synthesis result of `config` (its filter, γ, and the gains file the synthesis
// library writes for it), with `origin`.
ObtainedGains obtained_from(const hinf::synth::SynthesisResult& result, const hinf::synth::SynthConfig& config,
                            const std::string& origin);

}  // namespace hinf::sim
