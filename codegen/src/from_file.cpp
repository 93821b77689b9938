// generate_c_for_file (codegen.hpp): the text of a gains or controller file to the four
// files, by the file's own `format:`.
#include <string>

#include "hinf/codegen/codegen.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "hinf/runtime_yaml/controller_file.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"

namespace hinf::codegen {
namespace {

// True if the YAML text states `format: <format>` at its top level.
bool declares_format(const std::string& text, const std::string& path, const std::string& format) {
  const YamlReader reader(path);
  const YAML::Node root = reader.load(text, "empty file; expected a gains or controller file");
  return root.IsMap() && root["format"] && root["format"].IsScalar() && root["format"].Scalar() == format;
}

}  // namespace

GeneratedFiles generate_c_for_file(const std::string& text, const std::string& path, const CodegenOptions& options) {
  if (declares_format(text, path, "hinf-controller/1"))
    return generate_controller_c(runtime_yaml::parse_controller_yaml(text, path), options);
  return generate_c(runtime_yaml::parse_gains_yaml(text, path), options);
}

}  // namespace hinf::codegen
