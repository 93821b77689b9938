// `hinf-synth codegen` from the command line: exit codes, messages, files left.
// Runs the real hinf-synth, or the program named by $HINF_CODEGEN_CLI.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "codegen_test_support.hpp"
#include "hinf/runtime/lti_controller.hpp"
#include "hinf/runtime_yaml/controller_file.hpp"

#include <sstream>

namespace {

using hinf::test::TempDir;

std::string cli() {
  const char* env = std::getenv("HINF_CODEGEN_CLI");
  return env != nullptr && *env != '\0' ? env : HINF_TEST_CODEGEN_CLI;
}

hinf::test::CommandResult codegen(const std::string& args) {
  return hinf::test::run(cli() + " codegen " + args);
}

TEST(CodegenCli, WritesTheFourFilesAndIsByteIdenticalAcrossRuns) {
  TempDir dir;
  const std::string gains = HINF_TEST_PAPER_GAINS;
  auto r = codegen(gains + " --prefix nav -o " + (dir / "a"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(hinf::test::list_dir(dir / "a"), "nav.c nav.h nav_check.c nav_vectors.h");
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // a timestamp would change
  r = codegen(gains + " --prefix nav -o " + (dir / "b"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"nav.c", "nav.h", "nav_check.c", "nav_vectors.h"})
    EXPECT_EQ(hinf::test::read_text(dir / "a/" + f), hinf::test::read_text(dir / "b/" + f)) << f;
  // Regenerating over existing files replaces them.
  r = codegen(gains + " --prefix nav -o " + (dir / "a") + " --real float");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(hinf::test::read_text(dir / "a/nav.h").find("float x[NAV_NX]"), std::string::npos);
  EXPECT_EQ(hinf::test::list_dir(dir / "a"), "nav.c nav.h nav_check.c nav_vectors.h");
}

TEST(CodegenCli, BadPrefixExits2AndWritesNothing) {
  TempDir dir;
  for (const char* prefix : {"1abc", "int", "nav-x", "_x", "strx"}) {
    const auto r = codegen(std::string(HINF_TEST_PAPER_GAINS) + " --prefix " + prefix +
                           " -o " + (dir / "out"));
    EXPECT_EQ(r.exit_code, 2) << prefix << ": " << r.output;
    EXPECT_NE(r.output.find(std::string("--prefix '") + prefix + "'"), std::string::npos)
        << r.output;
  }
  EXPECT_EQ(hinf::test::list_dir(dir.path()), "(empty)");
}

// --tustin is refused, naming it, unless it is a positive finite period for a continuous-time
// controller file with its config (issue 34: --tustin nan was silently ignored).
TEST(CodegenCli, TustinPeriodThatCannotApplyExits2AndWritesNothing) {
  TempDir dir;
  const std::string gains = HINF_TEST_PAPER_GAINS;
  for (const char* period : {"nan", "inf", "0", "-0.1"}) {
    const auto r = codegen(gains + " --prefix nav -o " + (dir / "out") + " --tustin " + period);
    EXPECT_EQ(r.exit_code, 2) << period << ": " << r.output;
    EXPECT_NE(r.output.find(std::string("--tustin = ") + period + ": must be a positive, finite period"),
              std::string::npos) << period << ": " << r.output;
  }
  auto r = codegen(gains + " --prefix nav -o " + (dir / "out") + " --tustin 0.1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--tustin: give --config CONFIG"), std::string::npos) << r.output;
  const std::string controller_config = std::string(HINF_TEST_CONTROLLERS_DIR) + "/double-integrator.yaml";
  r = codegen(gains + " --prefix nav -o " + (dir / "out") + " --zoh 0.1 --config " + controller_config);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("expected 'hinf-controller/1'"), std::string::npos) << r.output;
  r = codegen(gains + " --prefix nav -o " + (dir / "out") + " --config " + controller_config);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--config: only with --tustin or --zoh"), std::string::npos) << r.output;
  EXPECT_EQ(hinf::test::list_dir(dir.path()), "(empty)");
}

TEST(CodegenCli, BadGainsFileExits2AndWritesNothing) {
  TempDir dir;
  hinf::test::write_text(dir / "bad.yaml",
                         "format: hinf-gains/1\nfilter:\n  A_F: [[1, 0], [0, 1]]\n"
                         "  B_F: [[1], [1], [1]]\n  C_F: [[1, 0]]\n");
  auto r = codegen((dir / "bad.yaml") + " --prefix nav -o " + (dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("bad.yaml"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("filter.B_F"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("got 3x1"), std::string::npos) << r.output;
  r = codegen((dir / "missing.yaml") + " --prefix nav -o " + (dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("missing.yaml"), std::string::npos) << r.output;
  EXPECT_EQ(hinf::test::list_dir(dir.path()), "bad.yaml");
}

TEST(CodegenCli, UnwritableOutputExits2AndLeavesNothing) {
  TempDir dir;
  hinf::test::write_text(dir / "file", "x");
  // --out is a regular file; --out lies under a regular file.
  for (const std::string& out : {dir / "file", dir / "file/sub"}) {
    const auto r = codegen(std::string(HINF_TEST_PAPER_GAINS) + " --prefix nav -o " + out);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("cannot write"), std::string::npos) << r.output;
  }
  EXPECT_EQ(hinf::test::list_dir(dir.path()), "file");
  EXPECT_EQ(hinf::test::read_text(dir / "file"), "x");
  // A target that is in the way (nav.c is a directory): rolled back completely.
  std::filesystem::create_directories(dir / "out/nav.c");
  const auto r = codegen(std::string(HINF_TEST_PAPER_GAINS) + " --prefix nav -o " +
                         (dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(hinf::test::list_dir(dir / "out"), "nav.c");
}

TEST(CodegenCli, BadOptionsExit2) {
  TempDir dir;
  const std::string g = HINF_TEST_PAPER_GAINS;
  EXPECT_EQ(codegen(g + " --prefix nav -o " + (dir / "o") + " --real half").exit_code, 2);
  EXPECT_EQ(codegen(g + " -o " + (dir / "o")).exit_code, 2);              // no --prefix
  EXPECT_EQ(codegen(g + " --prefix nav").exit_code, 2);                      // no --out
  EXPECT_EQ(codegen("--prefix nav -o " + (dir / "o")).exit_code, 2);      // no gains file
  EXPECT_EQ(codegen(g + " --prefix nav -o " + (dir / "o") + " --vector-steps 0").exit_code, 2);
  EXPECT_EQ(hinf::test::list_dir(dir.path()), "(empty)");
}

}  // namespace

namespace {

// A discrete-time controller file (docs/maths.md (146)), D_K ≠ 0: its generated step, compiled
// with gcc and driven by a small main, against the runtime's LtiController (an independent
// implementation) on the same inputs.
TEST(CodegenCli, ControllerFileStepMatchesTheRuntimeController) {
  TempDir dir;
  const std::string config = std::string(HINF_TEST_CONTROLLERS_DIR) + "/double-integrator-discrete.yaml";
  auto r = hinf::test::run(cli() + " solve " + config + " -o " + (dir / "k.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = codegen((dir / "k.yaml") + " --prefix hold -o " + (dir / "c"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string h = hinf::test::read_text(dir / "c/hold.h");
  EXPECT_NE(h.find("#define HOLD_NU 1"), std::string::npos) << h;
  EXPECT_NE(h.find("#define HOLD_NY 1"), std::string::npos) << h;
  EXPECT_NE(hinf::test::read_text(dir / "c/hold.c").find("hold_D_K"), std::string::npos);
  hinf::test::write_text(dir / "c/drive.c",
                         "#include <stdio.h>\n#include \"hold.h\"\n"
                         "int main(void) {\n  hold_state s; double u0[HOLD_NU] = {0}; double u[HOLD_NU];\n"
                         "  hold_init(&s, u0);\n  for (int k = 0; k < 40; ++k) {\n"
                         "    double y[HOLD_NY]; y[0] = (double)(k % 7) - 3.0;\n"
                         "    hold_step(&s, y, u); printf(\"%.17g\\n\", u[0]);\n  }\n  return 0;\n}\n");
  r = hinf::test::run("cd " + (dir / "c") + " && gcc -std=c99 -O2 -Wall -Wextra -Werror hold.c drive.c -o drive && ./drive");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto file = hinf::runtime_yaml::load_controller_file(dir / "k.yaml");
  ASSERT_GT(file.D_K.cwiseAbs().maxCoeff(), 0.0);  // the feedthrough is exercised
  hinf::runtime::LtiController k(file.A_K, file.B_K, file.C_K, file.D_K);
  std::istringstream out(r.output);
  for (int step = 0; step < 40; ++step) {
    Eigen::VectorXd y(1);
    y << static_cast<double>(step % 7) - 3.0;
    double u_c = 0;
    ASSERT_TRUE(out >> u_c) << step;
    const double u = k.step(y)(0);
    EXPECT_NEAR(u_c, u, 1e-12 * (1 + std::abs(u))) << step;
  }
  r = hinf::test::run("cd " + (dir / "c") + " && gcc -std=c99 hold.c hold_check.c -o check && ./check");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(CodegenCli, ContinuousControllerNeedsTustin) {
  TempDir dir;
  const std::string config = std::string(HINF_TEST_CONTROLLERS_DIR) + "/double-integrator.yaml";
  auto r = hinf::test::run(cli() + " solve " + config + " -o " + (dir / "k.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = codegen((dir / "k.yaml") + " --prefix hold -o " + (dir / "c"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--tustin PERIOD"), std::string::npos) << r.output;
  EXPECT_EQ(hinf::test::list_dir(dir / "c"), "");
  r = codegen((dir / "k.yaml") + " --prefix hold -o " + (dir / "c") + " --tustin 0.1");
  EXPECT_EQ(r.exit_code, 2) << r.output;  // the sampled loop is certified on the config's plant
  EXPECT_NE(r.output.find("give --config CONFIG"), std::string::npos) << r.output;
  r = codegen((dir / "k.yaml") + " --prefix hold -o " + (dir / "c") + " --tustin 0.1 --config " + config);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("certified: the sampled loop's l2 gain from w to z is at most"), std::string::npos);
  const std::string header = hinf::test::read_text(dir / "c/hold.h");
  EXPECT_NE(header.find("Sample time: 0.10000000000000001 s"), std::string::npos);
  EXPECT_NE(header.find("of the sampled loop"), std::string::npos) << header;
  EXPECT_EQ(header.find("Gamma (certified l2-gain bound): not recorded"), std::string::npos) << header;
  // the discrete controller file beside the code: verify reads it on the config's sampled plant
  r = hinf::test::run(cli() + " verify " + config + " " + (dir / "c/hold_controller.yaml"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // a period at which the sampled loop is unstable: exit 1, the reason, nothing written
  r = codegen((dir / "k.yaml") + " --prefix hold -o " + (dir / "slow") + " --zoh 2 --config " + config);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("NOT certified: the sampled loop is unstable"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "slow"));
}

}  // namespace
