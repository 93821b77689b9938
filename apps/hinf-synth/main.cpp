// hinf-synth: robust H∞ filter synthesis, certification, analysis and code generation.
#include <algorithm>
#include <csignal>
#include <memory>
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

namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 ok, 1 a check failed (verify, check), 2 invalid input (the key, dimension or value is named), "
    "3 infeasible or ill-posed (with its certificate), 4 numerical failure. Conventions: docs/cli.md.";

// One worked example per subcommand, shown at the end of its --help; each runs as written
// from the source tree after a build (tests/docs/documented_examples.py runs them).
const char* example_of(const std::string& name) {
  if (name == "solve") return "hinf-synth solve configs/paper-dbar0.05.yaml -o gains.yaml   # -v: iteration table; --json";
  if (name == "kalman") return "hinf-synth kalman configs/paper-dbar0.05.yaml -o kalman.yaml";
  if (name == "analyze") return "hinf-synth analyze configs/paper-dbar0.05.yaml configs/paper-published-gains.yaml --json";
  if (name == "export-sdpa") return "hinf-synth export-sdpa configs/paper-dbar0.05.yaml -o paper.dat-s   # then: csdp paper.dat-s";
  if (name == "verify") return "hinf-synth verify configs/paper-dbar0.05.yaml gains.yaml";
  if (name == "check") return "hinf-synth check configs/paper-dbar0.05.yaml --golden tests/golden/paper-dbar0.05.yaml";
  if (name == "codegen") return "hinf-synth codegen gains.yaml --prefix nav -o generated/";
  if (name == "sweep") return "hinf-synth sweep configs/paper-dbar0.05.yaml --param delta_bar=0:0.1:1 -o g.csv --plot g.png";
  if (name == "compare") return "hinf-synth compare configs/paper-dbar0.05.yaml gains.yaml --plot sigma.png";
  return "hinf-synth solve configs/paper-dbar0.05.yaml -o gains.yaml";
}

// The long options of subcommand `sub` (and the app's own).
std::vector<std::string> long_options(const CLI::App& app, const CLI::App* sub) {
  std::vector<std::string> names{"--help", "--version"};
  for (const CLI::App* a : {&app, sub})
    if (a)
      for (const CLI::Option* o : a->get_options())
        for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
  return names;
}

// A mistyped long option is named (with the closest one) before CLI11 would report a
// missing required option instead ("--output is required" for "--ouput").
bool refuse_unknown_long_option(const CLI::App& app, int argc, char** argv) {
  const CLI::App* sub = nullptr;
  for (int i = 1; i < argc && !sub; ++i)
    for (const CLI::App* s : app.get_subcommands({}))
      if (s->get_name() == argv[i]) sub = s;
  const std::vector<std::string> names = long_options(app, sub);
  for (int i = 1; i < argc; ++i) {
    std::string word = argv[i];
    if (word == "--") break;  // what follows is positional
    if (word.rfind("--", 0) != 0) continue;
    word = word.substr(0, word.find('='));
    if (std::find(names.begin(), names.end(), word) != names.end()) continue;
    std::cerr << "hinf-synth: error: unknown option '" << word << "'";
    if (const auto guess = hinf::closest_match(word, names)) std::cerr << " (did you mean '" << *guess << "'?)";
    std::cerr << " (hinf-synth " << (sub ? sub->get_name() + " " : std::string()) << "--help)\n";
    return true;
  }
  return false;
}

}  // namespace

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
  for (CLI::App* sub : app.get_subcommands({})) {
    sub->footer(std::string("Example: ") + example_of(sub->get_name()) + "\n" + kExitCodes);
    sub->set_version_flag("--version", "hinf-synth " HINF_VERSION);
  }
  app.footer(std::string("Example: ") + example_of("") + "\n" + kExitCodes);
  // `hinf-synth help [SUBCOMMAND]`: the same as --help
  auto* help = app.add_subcommand("help", "this help, or a subcommand's: hinf-synth help solve");
  auto topic = std::make_shared<std::string>();
  help->add_option("subcommand", *topic, "the subcommand");
  help->callback([&app, &action, topic, help] {
    action = [&app, topic, help]() -> int {
      const CLI::App* target = &app;
      if (!topic->empty()) {
        target = nullptr;
        for (const CLI::App* s : app.get_subcommands({}))
          if (s->get_name() == *topic && s != help) target = s;
        if (!target) throw hinf::Error(hinf::ErrorCode::InvalidInput, "help: no subcommand '" + *topic + "'");
      }
      std::cout << target->help();
      return 0;
    };
  });
  if (refuse_unknown_long_option(app, argc, argv)) return hinf::exit_code(ErrorCode::InvalidInput);
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
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "hinf-synth: error: " << e.what() << " (hinf-synth --help)\n";
    return hinf::exit_code(ErrorCode::InvalidInput);
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
