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

}  // namespace hinf
