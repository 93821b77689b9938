// The sections of a config file (docs/file-formats.md): each reads one top-level key.
#pragma once
#include <yaml-cpp/yaml.h>

#include "hinf/common/yaml_reader.hpp"
#include "hinf/synth/hill_plant.hpp"
#include "hinf/synth/validate_plant.hpp"
#include "hinf/synth/sampled_plant.hpp"
#include "hinf/synth/settings.hpp"
#include <optional>

namespace hinf::synth {

// `system:` (A, B, C, D, L, optional G) and the optional `uncertainty:` (H, E); `uncertainty` may be
// an undefined node. Entries are checked here; shapes by validate_plant (the caller).
// With `sample_time` the matrices are continuous-time and `sampling` is set (the caller
// samples them after validate_plant, docs/maths.md §19).
Plant read_system_section(const YamlReader& reader, const YAML::Node& system,
                          const YAML::Node& uncertainty, std::optional<SamplingSpec>& sampling);

// `hill:`; values and shapes are checked by validate_hill_model (the caller).
HillPlantSpec read_hill_section(const YamlReader& reader, const YAML::Node& hill);

// `solver:`; one key per field of Settings; ranges are checked by Settings::validate.
Settings read_solver_section(const YamlReader& reader, const YAML::Node& solver);

// `filter:` {form: auto | augmented | observer} (docs/maths.md §18.4).
FormChoice read_filter_section(const YamlReader& reader, const YAML::Node& filter);

}  // namespace hinf::synth
