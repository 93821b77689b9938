// The sections of a config file (docs/file-formats.md): each reads one top-level key.
#pragma once
#include <yaml-cpp/yaml.h>

#include "hinf/common/yaml_reader.hpp"
#include "hinf/synth/hill_plant.hpp"
#include "hinf/synth/validate_plant.hpp"
#include "hinf/synth/sampled_plant.hpp"
#include "hinf/synth/settings.hpp"
#include "hinf/synth/parametric_uncertainty.hpp"
#include "config/affine_expression.hpp"
#include <optional>

namespace hinf::synth {

// `system:` (A, B, C, D, L, optional G) and the optional `uncertainty:` (H, E); `uncertainty` may be
// an undefined node. Entries are checked here; shapes by validate_plant (the caller).
// With `sample_time` the matrices are continuous-time and `sampling` is set (the caller
// samples them after validate_plant, docs/maths.md §19).
// With named parameters (`model` not empty) the entries of A may be affine expressions of
// them and of the constants, the other matrices' entries expressions of the constants; H and
// E are then built from A's parameter coefficients (docs/maths.md §22), and `uncertainty`
// must be undefined.
struct ParameterModel {
  ExpressionSymbols symbols;
  std::vector<UncertainParameter> parameters;
  bool block_per_parameter = true;  // uncertainty_blocks: per_parameter (true) | full (docs/maths.md §23)
};
// `parameter_blocks`: the named parameters that enter A, with their columns of H (empty
// without `parameters:`).
Plant read_system_section(const YamlReader& reader, const YAML::Node& system,
                          const YAML::Node& uncertainty, std::optional<SamplingSpec>& sampling,
                          const ParameterModel& model, std::vector<ParameterBlock>& parameter_blocks);

// `constants:` {name: number} and `parameters:` {name: {nominal, range: [low, high]}}; either
// node may be undefined. Names are identifiers, each declared once.
// `uncertainty_blocks` (per_parameter | full; only with `parameters`) may be undefined.
ParameterModel read_parameter_sections(const YamlReader& reader, const YAML::Node& constants,
                                       const YAML::Node& parameters, const YAML::Node& blocks);

// `hill:`; values and shapes are checked by validate_hill_model (the caller).
HillPlantSpec read_hill_section(const YamlReader& reader, const YAML::Node& hill);

// `solver:`; one key per field of Settings; ranges are checked by Settings::validate.
Settings read_solver_section(const YamlReader& reader, const YAML::Node& solver);

// `filter:` {form: auto | augmented | observer (docs/maths.md §18.4), estimate: predicted |
// filtered (§18.6)} into settings.form, settings.estimate.
void read_filter_section(const YamlReader& reader, const YAML::Node& filter, Settings& settings);

}  // namespace hinf::synth
