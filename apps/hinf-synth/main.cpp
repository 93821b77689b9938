// hinf-synth: robust H∞ filter synthesis, certification, analysis and code generation.
#include <algorithm>
#include <csignal>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "commands.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/common/suggest.hpp"
#include "hinf/common/error.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) makes write() fail with EFBIG, reported by the atomic
  // writer with the temporary removed, instead of killing the process mid-file.
  std::signal(SIGXFSZ, SIG_IGN);
  hinf::remove_temporaries_on_signals();  // Ctrl-C or a kill leaves no temporary
#if defined(__GLIBC__)
  // MUMPS allocates and frees its workspace at every one of Ipopt's factorisations (and
  // the barrier's Hessian is ~N² doubles): served by mmap, or returned to the kernel by a
  // heap trim, every such block page-faults again when touched. Keep blocks up to 32 MiB
  // on the heap and 16 MiB of slack at its top. Measured (perf stat, page faults):
  // paper 1194 → 1009 (−5 % CPU), random n = 10 19 600 → 3 540, n = 16 59 700 → 19 100
  // (docs/benchmarks.md).
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
  mallopt(M_TOP_PAD, 16 << 20);
#endif
  using hinf::Error;
  using hinf::ErrorCode;
  CLI::App app{"hinf-synth " HINF_VERSION
               ": certified robust H-infinity filters for uncertain discrete-time plants"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hinf-synth " HINF_VERSION);
  hinf::cli::Action action;
  hinf::cli::add_solve(app, action);
  hinf::cli::add_kalman(app, action);
  hinf::cli::add_analyze(app, action);
  hinf::cli::add_export_sdpa(app, action);
  hinf::cli::add_verify(app, action);
  hinf::cli::add_check(app, action);
  hinf::cli::add_codegen(app, action);
  hinf::cli::add_sweep(app, action);
  hinf::cli::add_compare(app, action);
  // A mistyped subcommand would otherwise only get CLI11's "A subcommand is required".
  if (argc >= 2 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    const std::string word = argv[1];
    if (std::find(names.begin(), names.end(), word) == names.end()) {
      std::cerr << "hinf-synth: error: unknown subcommand '" << word << "'";
      if (const auto guess = hinf::closest_match(word, names)) std::cerr << " (did you mean '" << *guess << "'?)";
      std::cerr << "; subcommands:";
      for (const std::string& n : names) std::cerr << " " << n;
      std::cerr << " (hinf-synth --help)\n";
      return hinf::exit_code(ErrorCode::InvalidInput);
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : hinf::exit_code(ErrorCode::InvalidInput);
  }
  try {
    return action ? action() : 0;
  } catch (const Error& e) {
    std::cerr << "hinf-synth: error: " << e.what() << "\n";
    return hinf::exit_code(e.code());
  } catch (const std::bad_alloc&) {
    // Inputs are capped before allocation and the solver's memory model is checked
    // against solver.max_memory_mb, so this is a machine (or ulimit -v) smaller than that.
    std::cerr << "hinf-synth: error: out of memory: this machine (or its ulimit -v) cannot provide the memory "
                 "the problem needs; lower solver.max_memory_mb to what it has, and the solve is refused "
                 "up front with its estimate\n";
    return hinf::exit_code(ErrorCode::InvalidInput);
  } catch (const std::exception& e) {
    std::cerr << "hinf-synth: internal error: " << e.what() << "\n";
    return hinf::exit_code(ErrorCode::NumericalFailure);
  }
}
