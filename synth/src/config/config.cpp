// parse_config: the top level of a config (docs/file-formats.md, "Config").
#include "hinf/synth/validate_plant.hpp"
#include "config/sections.hpp"
#include "config/sha256.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {
namespace {

// The node a key path ("hill.chaser_mass", "system.B") names, or an undefined node, so
// that errors found after reading (validate_plant, validate_hill_model,
// Settings::validate) still carry a file:line:col. The checks name the key in
// Error::key(); the message is never parsed.
YAML::Node node_of_key(const YAML::Node& root, const std::string& path) {
  YAML::Node node = root;
  size_t start = 0;
  for (;;) {
    const size_t dot = path.find('.', start);
    const std::string key =
        path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    const YAML::Node& parent = node;  // const lookup: never inserts into the tree
    if (key.empty() || !parent.IsMap() || !parent[key]) return YAML::Node();
    node.reset(parent[key]);
    if (dot == std::string::npos) return node;
    start = dot + 1;
  }
}

// Runs a check that throws Error(InvalidInput) naming a field of what was read; re-keys
// it to the field's key path in the file (key_of(field)) and prefixes the message with
// the location of that key.
template <typename Check, typename KeyOf>
void located(const YamlReader& reader, const YAML::Node& root, KeyOf&& key_of, Check&& check) {
  try {
    check();
  } catch (const Error& e) {
    if (e.code() != ErrorCode::InvalidInput) throw;
    const Error keyed = e.key().empty() ? e : e.rekeyed(key_of(e.key()));
    const YAML::Node at = node_of_key(root, keyed.key());
    throw Error(ErrorCode::InvalidInput,
                (at ? reader.location(at) : reader.source()) + ": " + keyed.what(), keyed.key());
  }
}

// Where each field of the plant, the Hill model and the settings is spelt in a config.
std::string system_key(const std::string& field) {
  if (field == "F_blocks") return "uncertainty.blocks";
  return (field == "H" || field == "E" ? "uncertainty." : "system.") + field;
}
std::string hill_key(const std::string& field) { return "hill." + field; }
std::string solver_key(const std::string& field) { return "solver." + field; }
std::string kalman_key(const std::string& field) { return "kalman." + field; }

}  // namespace

std::optional<double> SynthConfig::sample_time() const {
  if (sampling) return sampling->sample_time;
  if (hill) return hill->sample_time;
  return std::nullopt;
}

SynthConfig parse_config(const std::string& yaml_text, const std::string& source_name) {
  SynthConfig config;
  config.path = source_name;
  config.sha256 = sha256_hex(yaml_text);
  const YamlReader reader(source_name);

  const YAML::Node root =
      reader.load(yaml_text, "empty config; expected a map with 'system' or 'hill'");
  if (root.IsMap() && root["controller"])
    reader.fail(root["controller"], "a controller config (controller:, docs/maths.md §26): this command takes a "
                            "filter config (system: or hill:); solve, verify, analyze, check and export-sdpa take both");
  reader.check_map(root, "", {"system", "uncertainty", "hill", "solver", "filter", "constants", "parameters",
                              "uncertainty_blocks", "kalman"});

  const YAML::Node system = root["system"];
  const YAML::Node hill = root["hill"];
  const YAML::Node uncertainty = root["uncertainty"];
  if (system && hill)
    reader.fail(hill, "the config has both 'system' and 'hill'; give exactly one");
  if (!system && !hill)
    reader.fail(root, "the config has neither 'system' nor 'hill'; give exactly one");
  if (hill && uncertainty)
    reader.fail(uncertainty, "'uncertainty' is only allowed with 'system'; with 'hill' the "
                             "uncertainty comes from hill.delta_bar (docs/maths.md §9.4)");

  const YAML::Node constants = root["constants"];
  const YAML::Node parameters = root["parameters"];
  if (hill && (constants || parameters || root["uncertainty_blocks"]))
    reader.fail(constants ? constants : parameters ? parameters : root["uncertainty_blocks"],
                "'constants' and 'parameters' are only allowed with 'system' (the hill model has hill.delta_bar)");
  if (uncertainty && parameters)
    reader.fail(uncertainty, "the config has both 'uncertainty' (H, E) and 'parameters'; give one: with "
                             "'parameters' the tool builds H and E from system.A (docs/maths.md §22)");

  try {
    if (system) {
      const ParameterModel model = read_parameter_sections(reader, constants, parameters, root["uncertainty_blocks"]);
      config.plant = read_system_section(reader, system, uncertainty, config.sampling, model, config.parameter_blocks);
      located(reader, root, system_key, [&] { validate_plant(config.plant); });
      if (config.sampling)
        located(reader, root, system_key, [&] { config.plant = sample_plant(config.plant, *config.sampling); });
    } else {
      HillPlantSpec model = read_hill_section(reader, hill);
      located(reader, root, hill_key, [&] { config.plant = build_hill_plant(model); });
      config.hill = std::move(model);
    }
    if (const YAML::Node solver = root["solver"]) {
      config.settings = read_solver_section(reader, solver);
      located(reader, root, solver_key, [&] { config.settings.validate(); });
    }
    if (const YAML::Node filter = root["filter"]) read_filter_section(reader, filter, config.settings);
    if (const YAML::Node kalman = root["kalman"]) {  // the Kalman predictor's covariances (docs/maths.md §20)
      const YamlMap k = reader.map(kalman, "kalman", {"Q", "R"});
      if (k.has("Q")) config.kalman_noise.Q = k.matrix("Q");
      if (k.has("R")) config.kalman_noise.R = k.matrix("R");
      located(reader, root, kalman_key, [&] { validate_kalman_noise(config.kalman_noise, config.plant); });
    }
  } catch (const YAML::Exception& e) {  // should not happen: every access is checked
    throw Error(ErrorCode::InvalidInput, source_name + ": YAML error: " + e.what());
  }
  return config;
}

}  // namespace hinf::synth
