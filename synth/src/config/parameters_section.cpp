// `constants:` and `parameters:` (docs/file-formats.md "parameters", docs/maths.md §22).
#include <algorithm>
#include <cctype>

#include "config/sections.hpp"
#include "hinf/common/number_text.hpp"

namespace hinf::synth {
namespace {

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

// The keys of a map of names, each an identifier not used before: not a constant or parameter
// already declared, and not twice in this map (YAML readers keep the last of two equal keys,
// which would silently change the plant).
std::vector<std::pair<std::string, YAML::Node>> named_entries(const YamlReader& reader, const YAML::Node& map,
                                                              const std::string& path, const ExpressionSymbols& seen) {
  if (!map.IsMap() || map.size() == 0) reader.fail(map, path + ": expected a non-empty map of names");
  std::vector<std::pair<std::string, YAML::Node>> out;
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string name = it->first.IsScalar() ? it->first.Scalar() : std::string();
    if (!is_identifier(name))
      reader.fail(it->first, path + ": '" + name + "' is not a name (a letter or _, then letters, digits or _)");
    const bool twice = std::any_of(out.begin(), out.end(), [&](const auto& entry) { return entry.first == name; });
    if (twice) reader.fail(it->first, path + "." + name + ": declared twice in '" + path + "'");
    if (seen.constants.count(name) > 0) reader.fail(it->first, path + "." + name + ": the name is already a constant");
    if (std::find(seen.parameters.begin(), seen.parameters.end(), name) != seen.parameters.end())
      reader.fail(it->first, path + "." + name + ": the name is already a parameter");
    out.emplace_back(name, it->second);
  }
  return out;
}

// At most this many parameters: each is a block of F and an LMI multiplier, and its
// coefficient matrix is n×n while H, E are built (a hostile config cannot ask for more
// than kMaxParameters·n² doubles, 128 MB at n = 1000).
constexpr std::size_t kMaxParameters = 16;

}  // namespace

ParameterModel read_parameter_sections(const YamlReader& reader, const YAML::Node& constants,
                                       const YAML::Node& parameters, const YAML::Node& blocks) {
  ParameterModel model;
  if (blocks && !parameters)
    reader.fail(blocks, "uncertainty_blocks: only with 'parameters' (with uncertainty: H, E, give uncertainty.blocks)");
  if (blocks) model.block_per_parameter = reader.choice(blocks, "uncertainty_blocks", {"per_parameter", "full"}) == "per_parameter";
  if (constants)
    for (const auto& [name, value] : named_entries(reader, constants, "constants", model.symbols))
      model.symbols.constants[name] = reader.finite_number(value, "constants." + name);
  if (!parameters) return model;
  if (parameters.IsMap() && parameters.size() > kMaxParameters)
    reader.fail(parameters, "parameters: " + std::to_string(parameters.size()) + " parameters; at most " +
                                std::to_string(kMaxParameters) + " (each is a block of the uncertainty and a multiplier)");
  for (const auto& [name, node] : named_entries(reader, parameters, "parameters", model.symbols)) {
    const std::string path = "parameters." + name;
    const YamlMap entry = reader.map(node, path, {"nominal", "range"});
    const Eigen::VectorXd range = entry.vector("range", 2);
    UncertainParameter p{name, 0, range(0), range(1)};
    if (!(p.low < p.high))
      entry.fail("range", "[" + number_text(p.low) + ", " + number_text(p.high) + "]: the lower end must be below the upper");
    p.nominal = entry.finite("nominal", 0.5 * (p.low + p.high));
    if (p.nominal < p.low || p.nominal > p.high)
      entry.fail_value("nominal", p.nominal, "must lie in the range [" + number_text(p.low) + ", " + number_text(p.high) + "]");
    model.symbols.parameters.push_back(name);
    model.parameters.push_back(p);
  }
  return model;
}

}  // namespace hinf::synth
