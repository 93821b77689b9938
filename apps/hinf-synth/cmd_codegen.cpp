// hinf-synth codegen GAINS.yaml --prefix NAME -o DIR [--real double|float] [--json]
// Writes DIR/NAME.h, DIR/NAME.c (the filter, C99), DIR/NAME_vectors.h and
// DIR/NAME_check.c (test vectors and an on-target check driver). docs/codegen.md.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/synth/api.hpp"  // json_schema
#include "hinf/common/input_file.hpp"
#include "hinf/codegen/codegen.hpp"

#ifndef HINF_VERSION
#error "HINF_VERSION must be defined by the build"
#endif

namespace hinf::cli {

void add_codegen(CLI::App& app, Action& action) {
  struct Args {
    std::string gains;
    std::string prefix;
    std::string out;
    std::string old_out;  // --out, the older spelling of -o/--output (docs/cli.md)
    std::string real = "double";
    int vector_steps = 50;
    std::optional<double> tustin;  // s; a continuous-time controller discretised at this period
    bool json = false;
    bool quiet = false;
    bool verbose = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "codegen", "Generate C99 code (no heap, no libm) for a filter (gains file) or a discrete-time controller (controller file)");
  cmd->add_option("GAINS", args->gains, "Gains file (format hinf-gains/1) or controller file (hinf-controller/1)")->required();
  cmd->add_option("--prefix", args->prefix,
                  "Symbol and file prefix, a C identifier (e.g. nav_filter)")
      ->required();
  auto* output = cmd->add_option("-o,--output", args->out, "Output directory (created if missing)");
  cmd->add_option("--out", args->old_out, "the older spelling of -o/--output")->group("")->excludes(output);
  cmd->add_option("--real", args->real, "Arithmetic type of the generated code")
      ->check(CLI::IsMember({"double", "float"}))
      ->capture_default_str();
  cmd->add_option("--vector-steps", args->vector_steps,
                  "Number of steps in the generated test vectors")
      ->check(CLI::Range(1, 2000))
      ->capture_default_str();
  cmd->add_option("--tustin", args->tustin,
                  "Period (s) at which a continuous-time controller file is discretised by Tustin's rule "
                  "(docs/maths.md (161))");
  add_quiet_flag(*cmd, args->quiet);
  add_verbose_flag(*cmd, args->verbose);
  cmd->add_flag("--json", args->json, "print JSON (schema hinf-synth.codegen/1: the files written) instead of text");
  cmd->callback([args, &action] {
    if (!args->old_out.empty()) {
      args->out = args->old_out;
      std::cerr << "hinf-synth: note: --out is the older spelling of -o/--output; it will go in a later version\n";
    }
    if (args->out.empty()) throw CLI::RequiredError("--output");
    action = [args]() -> int {
      hinf::codegen::CodegenOptions options;
      options.prefix = args->prefix;
      options.real = args->real == "float" ? hinf::codegen::CodegenOptions::Real::Float
                                           : hinf::codegen::CodegenOptions::Real::Double;
      options.generator = "hinf-synth " HINF_VERSION;
      options.vector_steps = args->vector_steps;
      options.tustin_period = args->tustin;
      hinf::codegen::validate_codegen_prefix(options.prefix);  // before touching any file
      const Stages stage(args->verbose, "codegen");
      const std::string text = stage("read " + args->gains, [&] {
        return hinf::read_input_file(args->gains, "gains or controller file", hinf::kMaxGainsBytes);
      });
      const hinf::codegen::GeneratedFiles files = stage("C generated and its test vectors computed", [&] {
        return hinf::codegen::generate_c_for_file(text, args->gains, options);
      });
      stage("wrote " + args->out, [&] { hinf::codegen::write_generated_files(files, args->out, {args->gains}); });
      Json written = Json::array();
      for (const auto& f : files.files) {
        const std::string path = (std::filesystem::path(args->out) / f.name).lexically_normal().string();
        if (!args->json && !args->quiet) std::cout << "wrote " << path << "\n";
        written.push_back({{"path", path}, {"bytes", f.contents.size()}});
      }
      if (args->json) {
        Json j;
        j["schema"] = synth::json_schema("codegen");
        j["input"] = args->gains;
        j["prefix"] = args->prefix;
        j["real"] = args->real;
        j["out"] = args->out;
        j["files"] = std::move(written);
        print_json(j);
      }
      return 0;
    };
  });
}

}  // namespace hinf::cli
