// hinf-synth codegen GAINS.yaml --prefix NAME -o DIR [--real double|float] [--json]
//                   [--tustin T | --zoh T  --config CONFIG]
// Writes DIR/NAME.h, DIR/NAME.c (the filter or controller, C99), DIR/NAME_vectors.h and
// DIR/NAME_check.c (test vectors and an on-target check driver); a continuous-time controller
// discretised at T (its sampled loop certified by the synthesis API's discretise job) also
// DIR/NAME_controller.yaml, the discrete controller file. docs/codegen.md.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/synth/api.hpp"  // json_schema, load_problem, Problem::discretise
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
    std::optional<double> tustin, zoh;  // s; a continuous-time controller discretised at this period
    std::string config;                 // its config, whose plant the sampled loop is certified on
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
  auto* tustin = cmd->add_option("--tustin", args->tustin,
                                 "Period (s) at which a continuous-time controller file is discretised by Tustin's "
                                 "rule (docs/maths.md (161)); needs --config: the sampled loop is certified");
  cmd->add_option("--zoh", args->zoh,
                  "Period (s) at which a continuous-time controller file is discretised by a zero-order hold "
                  "(docs/maths.md (161a)); needs --config")
      ->excludes(tustin);
  cmd->add_option("--config", args->config,
                  "The controller's config (with --tustin/--zoh): the loop of the discretised controller and the "
                  "plant sampled at the same period is certified on it, its gamma recorded in the code");
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
      hinf::codegen::validate_codegen_prefix(options.prefix);  // before touching any file
      const Stages stage(args->verbose, "codegen");
      // a continuous-time controller discretised, its sampled loop certified (docs/maths.md (161b))
      const std::optional<synth::DiscretiseOutcome> sampled = stage("discretise and certify the sampled loop", [&] {
        return synth::discretise_for_codegen(args->gains, args->config, args->tustin, args->zoh);
      });
      if (sampled && !sampled->holds) {
        if (!args->quiet) std::cout << (args->json ? sampled->json + "\n" : sampled->report);
        throw Error(ErrorCode::CheckFailed, args->gains + ": the sampled loop is not certified (" +
                                                (args->quiet ? "-q: not shown" : "above") + "); nothing written");
      }
      if (sampled && !args->json && !args->quiet) std::cout << sampled->report;
      const std::string text = sampled ? sampled->file : stage("read " + args->gains, [&] {
        return hinf::read_input_file(args->gains, "gains or controller file", hinf::kMaxGainsBytes);
      });
      hinf::codegen::GeneratedFiles files = stage("C generated and its test vectors computed", [&] {
        return hinf::codegen::generate_c_for_file(text, args->gains, options);
      });
      if (sampled) files.files.push_back({options.prefix + "_controller.yaml", sampled->file});
      std::vector<std::string> inputs{args->gains};
      if (!args->config.empty()) inputs.push_back(args->config);
      stage("wrote " + args->out, [&] { hinf::codegen::write_generated_files(files, args->out, inputs); });
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
        if (sampled) j["discretised"] = Json::parse(sampled->json);
        print_json(j);
      }
      return 0;
    };
  });
}

}  // namespace hinf::cli
