// with_value: a config's text with one scalar replaced in place (for `hinf-synth sweep`).
// The replacement is made in the text, not by re-emitting the YAML tree, so the result is
// read by the same strict reader with the same comments, layout and locations.
#include <string>
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
  const std::size_t pos = node.IsScalar() && node.Mark().pos >= 0 ? static_cast<std::size_t>(node.Mark().pos)
                                                                  : std::string::npos;
  const std::string& scalar = node.IsScalar() ? node.Scalar() : std::string();
  // Only a plain scalar is written in the text exactly as read (no quotes, no folding).
  if (pos == std::string::npos || node.Tag() != "?" || yaml_text.compare(pos, scalar.size(), scalar) != 0)
    throw Error(ErrorCode::InvalidInput,
                reader.location(node) + ": '" + key_path + "' is not a plain number; a swept parameter must be one",
                key_path);
  reader.number(node, key_path);  // a number today (the value replacing it is one)
  return yaml_text.substr(0, pos) + number_text(value) + yaml_text.substr(pos + scalar.size());
}

}  // namespace hinf::synth
