// Subcommands of hinf-synth: one file each (cmd_<name>.cpp).
// add_<name> registers the subcommand on `app`; when it is selected, its callback
// stores the work to do in `action`, which main() runs and turns into an exit code.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace hinf::cli {

using Action = std::function<int()>;

void add_solve(CLI::App& app, Action& action);
void add_kalman(CLI::App& app, Action& action);
void add_analyze(CLI::App& app, Action& action);
void add_export_sdpa(CLI::App& app, Action& action);
void add_verify(CLI::App& app, Action& action);
void add_check(CLI::App& app, Action& action);
void add_codegen(CLI::App& app, Action& action);
void add_sweep(CLI::App& app, Action& action);
void add_compare(CLI::App& app, Action& action);

}  // namespace hinf::cli
