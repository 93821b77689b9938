// `system:` + `uncertainty:` (docs/maths.md (1)–(4), (120): x(k+1) = (A + H F E) x + G u + B w,
// y = C x + D v, z = L x).
#include "config/sections.hpp"

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"

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

// A matrix of `system:` whose entries may be expressions (docs/maths.md §22): each scalar
// is read as an affine expression (a number is one), whose parameter
// coefficients are appended to `coefficients` (nullptr: no parameter may appear, as outside A).
struct Coefficient {
  std::size_t parameter;
  Eigen::Index row, col;
  double value;
};
Eigen::MatrixXd expression_matrix(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                                  const ParameterModel& model, std::vector<Coefficient>* coefficients) {
  const auto entry = [&](const YAML::Node& e, const std::string& entry_path, Eigen::Index r, Eigen::Index c) {
    if (!e.IsScalar()) return reader.finite_number(e, entry_path);  // names what it is instead
    AffineForm f;
    try {
      f = parse_affine_expression(e.Scalar(), model.symbols);
    } catch (const Error& err) {
      reader.fail(e, entry_path + ": " + err.what());
    }
    for (Eigen::Index i = 0; i < f.coefficients.size(); ++i) {
      if (f.coefficients(i) == 0) continue;
      if (!coefficients)
        reader.fail(e, entry_path + ": the parameter '" + model.parameters[static_cast<std::size_t>(i)].name +
                           "' may enter system.A only (the uncertainty is Delta A = H F E, docs/maths.md §22)");
      coefficients->push_back({static_cast<std::size_t>(i), r, c, f.coefficients(i)});
    }
    // A(ν): the nominal plant (docs/maths.md (136))
    double value = f.constant;
    for (Eigen::Index i = 0; i < f.coefficients.size(); ++i)
      value += f.coefficients(i) * model.parameters[static_cast<std::size_t>(i)].nominal;
    return value;
  };
  return reader.matrix(node, path, entry);
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

// `system:` with constants and parameters: H, E from A's parameter coefficients.
Plant read_parametric_system(const YamlReader& reader, const YAML::Node& system, const ParameterModel& model,
                             std::vector<ParameterBlock>& parameter_blocks) {
  const auto required = [&](const char* key, const char* what) {
    if (!system[key]) reader.fail(system, std::string("missing key 'system.") + key + "' (" + what + ")");
    return system[key];
  };
  std::vector<Coefficient> entries;
  Plant plant;
  plant.A = expression_matrix(reader, required("A", "n x n state matrix"), "system.A", model, &entries);
  plant.B = expression_matrix(reader, required("B", "n x p process-noise input"), "system.B", model, nullptr);
  plant.C = expression_matrix(reader, required("C", "m x n measurement matrix"), "system.C", model, nullptr);
  plant.D = expression_matrix(reader, required("D", "m x q measurement-noise input"), "system.D", model, nullptr);
  plant.L = expression_matrix(reader, required("L", "l x n estimated signal"), "system.L", model, nullptr);
  plant.G = system["G"] ? expression_matrix(reader, system["G"], "system.G", model, nullptr)
                        : Eigen::MatrixXd::Zero(plant.A.rows(), 0);
  std::vector<Eigen::MatrixXd> coefficients(model.parameters.size(),  // the shape of A (validate_plant: n×n)
                                            Eigen::MatrixXd::Zero(plant.A.rows(), plant.A.cols()));
  for (const Coefficient& e : entries) coefficients[e.parameter](e.row, e.col) = e.value;
  const UncertaintyFactors f = uncertainty_from_parameters(coefficients, model.parameters, plant.A.rows());
  plant.H = f.H;
  plant.E = f.E;
  if (model.block_per_parameter) plant.F_blocks = f.blocks;  // one multiplier per parameter (§23)
  parameter_blocks = f.parameter_blocks;
  return plant;
}

}  // namespace

Plant read_system_section(const YamlReader& reader, const YAML::Node& system,
                          const YAML::Node& uncertainty, std::optional<SamplingSpec>& sampling,
                          const ParameterModel& model, std::vector<ParameterBlock>& parameter_blocks) {
  reader.check_map(system, "system",
                   {"A", "B", "C", "D", "L", "G", "sample_time", "discretisation", "process_noise"});
  sampling = read_sampling(reader, system);
  if (!model.symbols.empty()) return read_parametric_system(reader, system, model, parameter_blocks);
  Plant plant;
  plant.A = required_matrix(reader, system, "system", "A", "n x n state matrix");
  plant.B = required_matrix(reader, system, "system", "B", "n x p process-noise input");
  plant.C = required_matrix(reader, system, "system", "C", "m x n measurement matrix");
  plant.D = required_matrix(reader, system, "system", "D", "m x q measurement-noise input");
  plant.L = required_matrix(reader, system, "system", "L", "l x n estimated signal");
  plant.G = system["G"] ? reader.matrix(system["G"], "system.G") : Eigen::MatrixXd::Zero(plant.A.rows(), 0);
  if (uncertainty) {
    reader.check_map(uncertainty, "uncertainty", {"H", "E", "blocks"});
    const char* both = "Delta A = H F E needs both H and E";
    plant.H = required_matrix(reader, uncertainty, "uncertainty", "H", both);
    plant.E = required_matrix(reader, uncertainty, "uncertainty", "E", both);
    if (const YAML::Node blocks = uncertainty["blocks"]) {  // F block-diagonal (docs/maths.md §23)
      if (!blocks.IsSequence() || blocks.size() == 0 || blocks.size() > kMaxMatrixDimension)
        reader.fail(blocks, "uncertainty.blocks: expected a list of at most " + std::to_string(kMaxMatrixDimension) +
                                " block sizes, e.g. [2, 1]");
      for (std::size_t b = 0; b < blocks.size(); ++b) {
        const int size = reader.integer(blocks[b], "uncertainty.blocks entry " + std::to_string(b + 1));
        if (size <= 0) reader.fail(blocks[b], "uncertainty.blocks entry " + std::to_string(b + 1) + " = " +
                                                  std::to_string(size) + ": must be > 0");
        plant.F_blocks.push_back(size);
      }
      if (plant.F_blocks.size() == 1) {  // one block: F full, and it must be all of F
        if (plant.F_blocks[0] != plant.H.cols() || plant.F_blocks[0] != plant.E.rows())
          reader.fail(blocks, "uncertainty.blocks: one block of size " + std::to_string(plant.F_blocks[0]) +
                                  ", but F is " + std::to_string(plant.E.rows()) + "x" + std::to_string(plant.H.cols()) +
                                  " (rows of E x columns of H); the blocks are square and cover F");
        plant.F_blocks.clear();
      }
    }
  } else {
    plant.H = Eigen::MatrixXd::Zero(plant.A.rows(), 0);
    plant.E = Eigen::MatrixXd::Zero(0, plant.A.cols());
  }
  return plant;
}

}  // namespace hinf::synth
