// The synthesis API (hinf/synth/api.hpp) called in-process — no subprocess, no files — gives
// what the hinf-synth executable gives on the same config, for every problem kind: the same
// file byte for byte (timing apart), the same reports for analyze --json, verify and check,
// the same SDPA export; and the registry picks each config's kind.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <regex>
#include <string>
#include <unistd.h>

#include "api_test_support.hpp"
#include "hinf/common/error.hpp"
#include "hinf/synth/api.hpp"

namespace fs = std::filesystem;

namespace {

using hinf::test::slurp;
using hinf::test::timing_apart;

struct Case {
  const char* config;  // relative to the source tree
  const char* kind;    // the kind the registry must pick
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.config; }

// Runs `hinf-synth ARGS`, its stdout into `stdout_file`; the exit status.
int hinf_synth(const std::string& args, const fs::path& stdout_file) {
  const std::string cmd = std::string(HINF_SYNTH_EXE) + " " + args + " > " + stdout_file.string() + " 2>/dev/null";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The solve report without its time ("[54 Newton iterations, 0.15 s]" → "[54 Newton iterations]").
std::string without_time(const std::string& report) {
  return std::regex_replace(report, std::regex(R"(, [0-9.e+-]+ s\])"), "]");
}

class SynthesisApi : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("synthesis_api_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_P(SynthesisApi, SameAsTheExecutable) {
  const Case c = GetParam();
  const std::string config = (fs::path(HINF_SOURCE_DIR) / c.config).string();
  const std::unique_ptr<hinf::synth::Problem> problem = hinf::synth::load_problem(config);
  EXPECT_EQ(problem->kind(), c.kind);
  EXPECT_EQ(problem->source(), config);

  // solve: the same file; the report the executable prints before "written to"
  const hinf::synth::SolveOutcome solved = problem->solve();
  const fs::path file = dir_ / "design.yaml";
  ASSERT_EQ(hinf_synth("solve " + config + " -o " + file.string(), dir_ / "solve.txt"), 0);
  EXPECT_TRUE(timing_apart(slurp(file)) == timing_apart(solved.file)) << c.config;
  EXPECT_EQ(without_time(slurp(dir_ / "solve.txt")), without_time(solved.report) + solved.file_contents + " written to " + file.string() + "\n");
  EXPECT_EQ(solved.file_contents, std::string(c.kind) == "filter" ? "gains" : "controller");
  EXPECT_GT(solved.gamma, 0);

  // analyze, verify and check of the executable's file
  ASSERT_EQ(hinf_synth("analyze " + config + " " + file.string() + " --json", dir_ / "analyze.txt"), 0);
  EXPECT_EQ(slurp(dir_ / "analyze.txt"), problem->analyze(file.string()).json + "\n");
  const hinf::synth::VerifyOutcome verified = problem->verify(file.string());
  EXPECT_TRUE(verified.holds);
  ASSERT_EQ(hinf_synth("verify " + config + " " + file.string(), dir_ / "verify.txt"), 0);
  EXPECT_EQ(slurp(dir_ / "verify.txt"), verified.report);
  const hinf::synth::CheckOutcome checked = problem->check(file.string(), 1e-6);
  EXPECT_TRUE(checked.same);
  EXPECT_EQ(checked.gamma_now, solved.gamma);  // deterministic: the same solve
  ASSERT_EQ(hinf_synth("check " + config + " --golden " + file.string(), dir_ / "check.txt"), 0);
  EXPECT_EQ(slurp(dir_ / "check.txt"), checked.report);

  // export-sdpa: the same bytes
  ASSERT_EQ(hinf_synth("export-sdpa " + config + " -o " + (dir_ / "lmi.dat-s").string(), dir_ / "export.txt"), 0);
  EXPECT_TRUE(slurp(dir_ / "lmi.dat-s") == problem->export_sdpa());
}

INSTANTIATE_TEST_SUITE_P(EveryKind, SynthesisApi,
                         ::testing::Values(Case{"configs/paper-dbar0.05.yaml", "filter"},
                                           Case{"tests/data/plants/double-integrator-filtered.yaml", "filter"},
                                           Case{"configs/tumbling-hold.yaml", "controller"}),
                         [](const auto& info) { return std::string(info.param.kind) + std::to_string(info.index); });

// The typed result is the kind's own: a filter's gains, a controller's realisation.
TEST(SynthesisApiResult, EachKindReturnsItsOwnTypedResult) {
  const auto filter = hinf::synth::load_problem(std::string(HINF_SOURCE_DIR) + "/configs/paper-dbar0.05.yaml")->solve();
  ASSERT_TRUE(std::holds_alternative<hinf::synth::SynthesisResult>(filter.result));
  EXPECT_EQ(std::get<hinf::synth::SynthesisResult>(filter.result).gamma, filter.gamma);
  EXPECT_TRUE(std::get<hinf::synth::SynthesisResult>(filter.result).certificate.passed);
}

// A config that is no kind's is refused by the fallback (filter) reader, naming the problem
// and with the exit code of invalid input; nothing is printed.
TEST(SynthesisApiRegistry, TextThatIsNoConfigIsInvalidInput) {
  try {
    hinf::synth::parse_problem("just words", "words.yaml");
    FAIL() << "no error";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("words.yaml"), std::string::npos) << e.what();
  }
}

}  // namespace
