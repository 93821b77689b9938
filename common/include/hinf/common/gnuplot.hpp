// Running Debian's gnuplot on a script file (plots of hinf-sim runs and of hinf-synth
// sweeps): the one place a subprocess is started.
#pragma once
#include <functional>
#include <string>

namespace hinf {

// Runs `gnuplot SCRIPT` (found on PATH) and waits for it: its exit status, or -1 if it
// could not be started.
int run_gnuplot(const std::string& script_path);

// A string as a gnuplot single-quoted literal ('' for ').
std::string gnuplot_quoted(const std::string& text);

// One png of `panels` panels stacked over a shared time axis: "set output PNG", a multiplot
// titled `title`, then per panel p its y label ylabel(p), the x label "time (s)" under the
// last panel only, the key outside right of the first panel only, the commands before(p) when
// given (the panel's arrows and labels), and "plot " curves(p).
std::string gnuplot_stacked_figure(const std::string& png, const std::string& title, int panels,
                                   const std::function<std::string(int)>& ylabel,
                                   const std::function<std::string(int)>& curves,
                                   const std::function<std::string(int)>& before = nullptr);

}  // namespace hinf
