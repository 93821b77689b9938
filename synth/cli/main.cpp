// hinf-synth: robust H∞ filter synthesis, certification, analysis and code generation.
#include <iostream>

#include "commands.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/synth/status.hpp"

int main(int argc, char** argv) {
  using hinf::synth::Error;
  using hinf::synth::ErrorCode;
  CLI::App app{"hinf-synth " HINF_VERSION
               ": certified robust H-infinity filters for uncertain discrete-time plants"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hinf-synth " HINF_VERSION);
  hinf::cli::Action action;
  hinf::cli::add_solve(app, action);
  hinf::cli::add_analyze(app, action);
  hinf::cli::add_export_sdpa(app, action);
  hinf::cli::add_verify(app, action);
  hinf::cli::add_check(app, action);
  hinf::cli::add_codegen(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : hinf::synth::exit_code(ErrorCode::InvalidInput);
  }
  try {
    return action ? action() : 0;
  } catch (const Error& e) {
    std::cerr << "hinf-synth: error: " << e.what() << "\n";
    return hinf::synth::exit_code(e.code());
  } catch (const hinf::runtime_yaml::GainsFileError& e) {
    std::cerr << "hinf-synth: error: " << e.what() << "\n";
    return hinf::synth::exit_code(ErrorCode::InvalidInput);
  } catch (const std::exception& e) {
    std::cerr << "hinf-synth: internal error: " << e.what() << "\n";
    return hinf::synth::exit_code(ErrorCode::NumericalFailure);
  }
}
