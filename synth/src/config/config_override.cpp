// with_value, with_parameter_value: a config's text with scalars replaced in place (for
// `hinf-synth sweep`).
// The replacement is made in the text, not by re-emitting the YAML tree, so the result is
// read by the same strict reader with the same comments, layout and locations.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "hinf/synth/config.hpp"

namespace hinf::synth {
namespace {

std::vector<std::string> split_key_path(const std::string& key_path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = key_path.find('.', start);
    parts.push_back(key_path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

// The position in `yaml_text` of the plain scalar `node` (written exactly as read: no quotes,
// no folding, no anchor — an anchored number is read elsewhere through its aliases, and its
// mark is the anchor's, so it fails the comparison below); Error InvalidInput naming
// `key_path` otherwise.
std::size_t plain_scalar_position(const YamlReader& reader, const YAML::Node& node, const std::string& yaml_text,
                                  const std::string& key_path, const std::string& what) {
  const std::size_t pos = node.IsScalar() && node.Mark().pos >= 0 ? static_cast<std::size_t>(node.Mark().pos)
                                                                  : std::string::npos;
  const std::string& scalar = node.IsScalar() ? node.Scalar() : std::string();
  if (pos == std::string::npos || node.Tag() != "?" || yaml_text.compare(pos, scalar.size(), scalar) != 0)
    throw Error(ErrorCode::InvalidInput, reader.location(node) + ": '" + key_path + "' is not a plain number; " + what,
                key_path);
  reader.number(node, key_path);  // a number today (the value replacing it is one)
  return pos;
}

// `yaml_text` with each (node, value) pair's plain scalar replaced by the value, from the last
// in the text to the first so that the earlier positions stay valid.
std::string with_replaced(const std::string& yaml_text, std::vector<std::pair<YAML::Node, std::size_t>> nodes,
                          const std::vector<double>& values) {
  std::vector<std::size_t> order(nodes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nodes[a].second > nodes[b].second; });
  std::string text = yaml_text;
  for (std::size_t i : order)
    text = text.substr(0, nodes[i].second) + number_text(values[i]) +
           text.substr(nodes[i].second + nodes[i].first.Scalar().size());
  return text;
}

}  // namespace

std::string with_value(const std::string& yaml_text, const std::string& source_name, const std::string& key_path,
                       double value) {
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(yaml_text, "empty config");
  YAML::Node node = root;
  for (const std::string& key : split_key_path(key_path)) {
    const YAML::Node& parent = node;  // const lookup: never inserts into the tree
    if (key.empty() || !parent.IsMap() || !parent[key])
      throw Error(ErrorCode::InvalidInput, source_name + ": '" + key_path +
                                               "' is not a key of the config; a swept parameter must be written in "
                                               "the config with a number, which the sweep replaces",
                  key_path);
    node.reset(parent[key]);
  }
  const std::size_t pos =
      plain_scalar_position(reader, node, yaml_text, key_path, "a swept parameter must be one");
  return with_replaced(yaml_text, {{node, pos}}, {value});
}

std::vector<std::string> parameter_names(const std::string& yaml_text, const std::string& source_name) {
  const YAML::Node root = YamlReader(source_name).load(yaml_text, "empty config");
  const YAML::Node parameters = root["parameters"];
  std::vector<std::string> names;
  if (parameters && parameters.IsMap())
    for (const auto& entry : parameters)
      if (entry.first.IsScalar()) names.push_back(entry.first.Scalar());
  return names;
}

std::string with_parameter_value(const std::string& yaml_text, const std::string& source_name,
                                 const std::string& name, double value) {
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(yaml_text, "empty config");
  const std::string path = "parameters." + name;
  const YAML::Node parameters = root["parameters"];
  if (!parameters || !parameters.IsMap() || !parameters[name])
    throw Error(ErrorCode::InvalidInput, source_name + ": '" + name + "' is not a parameter of the config", name);
  const YAML::Node entry = parameters[name];
  const std::string why = "a swept parameter's range and nominal must be plain numbers";
  if (!entry.IsMap() || !entry["range"] || !entry["range"].IsSequence() || entry["range"].size() != 2)
    throw Error(ErrorCode::InvalidInput, source_name + ": '" + path + "' has no range [low, high] to move", path);
  std::vector<std::pair<YAML::Node, std::size_t>> nodes;
  for (std::size_t i = 0; i < 2; ++i) {
    const YAML::Node end = entry["range"][i];
    nodes.emplace_back(end, plain_scalar_position(reader, end, yaml_text, path + ".range", why));
  }
  const double low = reader.number(nodes[0].first, path + ".range"), high = reader.number(nodes[1].first, path + ".range");
  const YAML::Node nominal_node = entry["nominal"];
  const double nominal = nominal_node ? reader.number(nominal_node, path + ".nominal") : 0.5 * (low + high);
  // The design point moves to `value`; the range keeps its offsets from it (docs/maths.md §21).
  std::vector<double> values{value - (nominal - low), value + (high - nominal)};
  if (nominal_node) {
    nodes.emplace_back(nominal_node, plain_scalar_position(reader, nominal_node, yaml_text, path + ".nominal", why));
    values.push_back(value);
  }
  return with_replaced(yaml_text, nodes, values);
}

}  // namespace hinf::synth
