// generate_c_for_file (codegen.hpp): the text of a gains or controller file to the four
// files, by the file's own `format:`.
#include <cmath>
#include <optional>
#include <string>

#include "hinf/codegen/codegen.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "hinf/models/controller.hpp"
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

// A controller file, discretised by Tustin's rule (docs/maths.md (161)) when it is
// continuous and a period is given.
runtime_yaml::ControllerFile controller_to_fly(const std::string& text, const std::string& path,
                                               std::optional<double> tustin_period) {
  runtime_yaml::ControllerFile k = runtime_yaml::parse_controller_yaml(text, path);
  if (!tustin_period) return k;
  if (k.discrete) throw Error(ErrorCode::InvalidInput, "--tustin: " + path + " is already a discrete-time controller", "tustin");
  const hinf::Controller d = hinf::tustin({k.A_K, k.B_K, k.C_K, k.D_K}, *tustin_period);
  // the certified gamma is the continuous loop's, not the sampled one's: not carried over
  return {true, *tustin_period, std::nullopt, k.tool, k.config_sha256, d.A_K, d.B_K, d.C_K, d.D_K};
}

}  // namespace

GeneratedFiles generate_c_for_file(const std::string& text, const std::string& path, const CodegenOptions& options) {
  const std::optional<double> period = options.tustin_period;
  if (period && !(std::isfinite(*period) && *period > 0))
    throw Error(ErrorCode::InvalidInput, "--tustin = " + number_text(*period) + ": must be a positive, finite period (s)",
                "tustin");
  if (declares_format(text, path, "hinf-controller/1"))
    return generate_controller_c(controller_to_fly(text, path, period), options);
  if (period)
    throw Error(ErrorCode::InvalidInput,
                "--tustin: " + path + " is not a controller file; Tustin's rule discretises a continuous-time controller",
                "tustin");
  return generate_c(runtime_yaml::parse_gains_yaml(text, path), options);
}

}  // namespace hinf::codegen
