// Test-only stand-in for hinf-synth with just the `codegen` subcommand, so the
// codegen tests do not depend on the rest of the tool building. Exception-to-exit
// mapping as in synth/cli/main.cpp and the ErrorCode comments of status.hpp.
#include <iostream>

#include "commands.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/synth/status.hpp"

namespace {
int exit_for(hinf::synth::ErrorCode code) {
  switch (code) {
    case hinf::synth::ErrorCode::Ok: return 0;
    case hinf::synth::ErrorCode::CheckFailed: return 1;
    case hinf::synth::ErrorCode::InvalidInput: return 2;
    case hinf::synth::ErrorCode::Infeasible: return 3;
    case hinf::synth::ErrorCode::NumericalFailure: return 4;
  }
  return 4;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hinf-synth (codegen only, test build)"};
  app.require_subcommand(1);
  hinf::cli::Action action;
  hinf::cli::add_codegen(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    return action ? action() : 0;
  } catch (const hinf::synth::Error& e) {
    std::cerr << "hinf-synth: error: " << e.what() << "\n";
    return exit_for(e.code());
  } catch (const hinf::runtime_yaml::GainsFileError& e) {
    std::cerr << "hinf-synth: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "hinf-synth: internal error: " << e.what() << "\n";
    return 4;
  }
}
