// C99 code generation for a synthesised filter (`hinf-synth codegen`).
//
// The generated code is data plus a fixed step, in the style of OSQP's generated
// code: no heap, no recursion, no libm, fixed loop bounds, static const data and a
// symbol prefix so that several filters link into one binary. Generation is pure
// (file names and contents in memory); writing them is a separate, atomic step.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hinf/runtime_yaml/controller_file.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"

namespace hinf::codegen {

struct CodegenOptions {
  enum class Real { Double, Float };

  std::string prefix;                 // C identifier, see validate_codegen_prefix
  Real real = Real::Double;           // arithmetic and storage type of the code
  std::string generator = "hinf-synth";  // provenance, e.g. "hinf-synth 0.1.0"
  int vector_steps = 50;              // length N of the test-vector sequence
  std::uint64_t vector_seed = 0x48494e46u;  // seed of the test-vector inputs ("HINF")
};

struct GeneratedFile {
  std::string name;      // file name only (no directory), e.g. "nav.h"
  std::string contents;
};

struct GeneratedFiles {
  std::string prefix;                // the prefix they were generated for
  std::vector<GeneratedFile> files;  // NAME.h, NAME.c, NAME_vectors.h, NAME_check.c
};

// Throws Error(InvalidInput) naming the rule when `prefix` cannot be used as the
// symbol/file prefix (not a C identifier, C/C++ keyword, reserved name, too long).
void validate_codegen_prefix(const std::string& prefix);

// Generates the four files for `gains` (docs/maths.md (5)-(6)). Throws Error(InvalidInput)
// for a bad prefix or options, or coefficients that do not fit the real type, and
// Error(NumericalFailure) if the test vectors overflow (a violently unstable filter).
GeneratedFiles generate_c(const runtime_yaml::GainsFile& gains, const CodegenOptions& options);

// The same four files for a discrete-time controller file (docs/maths.md (146)): NAME_NX,
// NAME_NY, NAME_NU; NAME_step(s, y, u) writes u = C_K x_K + D_K y, then x_K ← A_K x_K + B_K y;
// NAME_init(s, u0) sets x_K = pinv(C_K) u0 (u0 = 0: at rest). A continuous-time controller is
// refused (Error InvalidInput): discretise it first, its sampled loop certified
// (hinf::synth::Problem::discretise, `hinf-synth codegen --tustin T --config CONFIG`).
GeneratedFiles generate_controller_c(const runtime_yaml::ControllerFile& controller, const CodegenOptions& options);

// The four files for the text of a gains file (hinf-gains/1: generate_c) or a controller
// file (hinf-controller/1: generate_controller_c) read from `path`, by the file's own
// `format:`. Error(InvalidInput) as those.
GeneratedFiles generate_c_for_file(const std::string& text, const std::string& path, const CodegenOptions& options);

// Writes every file into `directory` (created if missing). All files are first
// written to temporary files in `directory` and then renamed, so a failure leaves
// no partial file behind; none of them replaces one of `inputs` (the same file, by
// device and inode). Files generated there before for another prefix (each carries
// " * Prefix: NAME") are never replaced, and a prefix that differs from one of them
// only in case is refused: the two would share macros and include guards (NAV_NX,
// NAV_H_GENERATED), and one file name on a case-insensitive file system. Throws
// Error(InvalidInput) naming the path or the other prefix.
void write_generated_files(const GeneratedFiles& files, const std::string& directory,
                           const std::vector<std::string>& inputs = {});

}  // namespace hinf::codegen
