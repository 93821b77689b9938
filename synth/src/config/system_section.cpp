// `system:` + `uncertainty:` (docs/maths.md (1)–(4), (120): x(k+1) = (A + H F E) x + G u + B w,
// y = C x + D v, z = L x).
#include "config/sections.hpp"

namespace hinf::synth {
namespace {

Eigen::MatrixXd required_matrix(const YamlReader& reader, const YAML::Node& section,
                                const std::string& section_name, const std::string& key,
                                const char* what) {
  const YAML::Node node = section[key];
  const std::string path = child_path(section_name, key);
  if (!node) reader.fail(section, "missing key '" + path + "' (" + what + ")");
  return reader.matrix(node, path);
}

// sample_time, discretisation, process_noise: the plant is continuous-time (docs/maths.md §19).
std::optional<SamplingSpec> read_sampling(const YamlReader& reader, const YAML::Node& system) {
  const YamlMap sys(reader, system, "system");
  if (!sys.has("sample_time")) {
    for (const char* key : {"discretisation", "process_noise"})
      if (sys.has(key))
        sys.fail(key, "only with system.sample_time (the matrices are then continuous-time); without it they "
                      "are the discrete plant");
    return std::nullopt;
  }
  SamplingSpec spec;
  spec.sample_time = sys.positive("sample_time");
  const std::string method = sys.choice("discretisation", {"zoh", "tustin", "euler"}, "zoh");
  spec.method = method == "euler"    ? models::Discretisation::Euler
                : method == "tustin" ? models::Discretisation::Tustin
                                     : models::Discretisation::ZeroOrderHold;
  spec.white_process_noise = sys.choice("process_noise", {"held", "white"}, "held") == "white";
  return spec;
}

}  // namespace

Plant read_system_section(const YamlReader& reader, const YAML::Node& system,
                          const YAML::Node& uncertainty, std::optional<SamplingSpec>& sampling) {
  reader.check_map(system, "system",
                   {"A", "B", "C", "D", "L", "G", "sample_time", "discretisation", "process_noise"});
  sampling = read_sampling(reader, system);
  Plant plant;
  plant.A = required_matrix(reader, system, "system", "A", "n x n state matrix");
  plant.B = required_matrix(reader, system, "system", "B", "n x p process-noise input");
  plant.C = required_matrix(reader, system, "system", "C", "m x n measurement matrix");
  plant.D = required_matrix(reader, system, "system", "D", "m x q measurement-noise input");
  plant.L = required_matrix(reader, system, "system", "L", "l x n estimated signal");
  plant.G = system["G"] ? reader.matrix(system["G"], "system.G") : Eigen::MatrixXd::Zero(plant.A.rows(), 0);
  if (uncertainty) {
    reader.check_map(uncertainty, "uncertainty", {"H", "E"});
    const char* both = "Delta A = H F E needs both H and E";
    plant.H = required_matrix(reader, uncertainty, "uncertainty", "H", both);
    plant.E = required_matrix(reader, uncertainty, "uncertainty", "E", both);
  } else {
    plant.H = Eigen::MatrixXd::Zero(plant.A.rows(), 0);
    plant.E = Eigen::MatrixXd::Zero(0, plant.A.cols());
  }
  return plant;
}

}  // namespace hinf::synth
