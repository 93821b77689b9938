// Running Debian's gnuplot on a script file (plots of hinf-sim runs and of hinf-synth
// sweeps): the one place a subprocess is started.
#pragma once
#include <string>

namespace hinf {

// Runs `gnuplot SCRIPT` (found on PATH) and waits for it: its exit status, or -1 if it
// could not be started.
int run_gnuplot(const std::string& script_path);

// A string as a gnuplot single-quoted literal ('' for ').
std::string gnuplot_quoted(const std::string& text);

}  // namespace hinf
