// Reading a synthesis config (docs/file-formats.md, "Config"): strict YAML, either the
// plant as matrices (`system:` + optional `uncertainty:`, docs/maths.md (1)–(4)) or the
// physical Hill model (`hill:`, docs/maths.md §9), plus optional `solver:` settings.
//
// Every failure is Error(InvalidInput) whose message names the file, the key path and,
// for matrices, the expected and actual dimensions. An unstable plant is NOT a config
// error (the solver's pre-flight reports it).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "hinf/synth/hill_plant.hpp"
#include "hinf/synth/parametric_uncertainty.hpp"
#include "hinf/synth/validate_plant.hpp"
#include "hinf/synth/sampled_plant.hpp"
#include "hinf/synth/settings.hpp"
#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

struct SynthConfig {
  Plant plant;                     // validated (validate_plant); discrete (sampled if given in continuous time)
  std::optional<SamplingSpec> sampling;  // set iff `system:` was continuous-time (sample_time)
  std::optional<HillPlantSpec> hill;   // set iff the config used `hill:`
  std::vector<ParameterBlock> parameter_blocks;  // `parameters:` that enter A, with their columns of H (§22)
  Settings settings;               // defaults overridden by `solver:`; validated
  KalmanNoise kalman_noise;        // `kalman: {Q, R}` (hinf-synth kalman, compare); empty: from B, D
  std::string sha256;              // SHA-256 of the config's exact bytes, lowercase hex
  std::string path;                // the path (or source name) it was read from
  // The sample time the filter must be run at, if the config states it (system.sample_time
  // or hill.sample_time), s.
  std::optional<double> sample_time() const;
};

// Reads the file's bytes, hashes them and parses them.
SynthConfig load_config(const std::string& path);

// Parses YAML text; `source_name` is used in messages and stored as `path`;
// sha256 is the hash of `yaml_text`.
SynthConfig parse_config(const std::string& yaml_text, const std::string& source_name);

// The config text with the plain number at `key_path` ("hill.delta_bar", "system.sample_time")
// replaced by `value`, everything else byte for byte (for `hinf-synth sweep`). Error
// InvalidInput naming the key if the config has no such key or it does not hold a plain number.
std::string with_value(const std::string& yaml_text, const std::string& source_name, const std::string& key_path,
                       double value);

// The names of the config's named parameters (`parameters: {name: …}`, §22), in file order.
std::vector<std::string> parameter_names(const std::string& yaml_text, const std::string& source_name);

// The config text with the named parameter `name` at `value` (docs/maths.md §21): its nominal
// (the design point) becomes `value` and its range moves with it, its offsets from the nominal
// unchanged; everything else byte for byte. Error InvalidInput naming the key if the
// parameter's range or nominal is not written as plain numbers.
std::string with_parameter_value(const std::string& yaml_text, const std::string& source_name,
                                 const std::string& name, double value);

}  // namespace hinf::synth
