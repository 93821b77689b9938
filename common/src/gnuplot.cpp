#include "hinf/common/gnuplot.hpp"

#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace hinf {

int run_gnuplot(const std::string& script_path) {
  std::string prog = "gnuplot";
  std::string script = script_path;
  char* argv[] = {prog.data(), script.data(), nullptr};
  pid_t pid = 0;
  if (posix_spawnp(&pid, "gnuplot", nullptr, nullptr, argv, environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string gnuplot_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string gnuplot_stacked_figure(const std::string& png, const std::string& title, int panels,
                                   const std::function<std::string(int)>& ylabel,
                                   const std::function<std::string(int)>& curves,
                                   const std::function<std::string(int)>& before) {
  std::string gp = "set output " + gnuplot_quoted(png) + "\nset multiplot layout " + std::to_string(panels) +
                   ",1 title " + gnuplot_quoted(title) + " noenhanced\n";
  for (int p = 0; p < panels; ++p)
    gp += "set ylabel " + gnuplot_quoted(ylabel(p)) + " noenhanced\n" +
          (p == panels - 1 ? "set xlabel 'time (s)'\n" : "unset xlabel\n") +
          (p == 0 ? "set key outside right top\n" : "unset key\n") + (before ? before(p) : std::string()) + "plot " +
          curves(p) + "\n";
  return gp + "unset multiplot\n";
}

}  // namespace hinf
