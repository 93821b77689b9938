// The golden-file workflow through the real hinf-synth binary (docs/maths.md [D14]):
//  - `check` compares filters as transfer functions: another realisation of the golden
//    filter passes, a 1% change of B_F or of gamma fails (exit 1);
//  - `verify` accepts the gains `solve` wrote, refuses a claimed gamma below what the
//    gains achieve, accepts a weaker claim; what it finds for the paper's published gains;
//  - two `solve` runs of one config give byte-identical files apart from `timing:`.
// Expected values come from the definitions (a similarity transform leaves the transfer
// function unchanged; scaling B_F by 1.01 scales it by 1.01; no filter beats the optimal
// gamma), never from the code under test.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>

#include "codegen_test_support.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"

namespace {

using hinf::runtime_yaml::GainsFile;
using hinf::test::TempDir;

const std::string kSource = HINF_SOURCE_DIR;
const std::string kSynth = HINF_SYNTH;

// The config the check/verify behaviour is exercised on: the paper's main case (n = 6,
// C_F entries 1e-6 of its diagonal, so realisation errors would show).
const std::string kConfig = kSource + "/configs/paper-dbar0.05.yaml";
const std::string kGolden = kSource + "/tests/golden/paper-dbar0.05.yaml";

hinf::test::CommandResult synth(const std::string& args) {
  const auto r = hinf::test::run(kSynth + " " + args);
  std::cout << "$ hinf-synth " << args << "\n" << r.output << "[exit " << r.exit_code << "]\n";
  return r;
}

void write_gains(const std::string& path, const GainsFile& g) {
  hinf::test::write_text(path, hinf::test::gains_yaml(g));
}

// A random, well-conditioned T = Q1 diag(s) Q2 (Q orthogonal, s in [0.5, 2]).
Eigen::MatrixXd well_conditioned(std::uint64_t seed, Eigen::Index n) {
  const Eigen::MatrixXd Q1 =
      Eigen::HouseholderQR<Eigen::MatrixXd>(hinf::test::random_matrix(seed, n, n)).householderQ();
  const Eigen::MatrixXd Q2 =
      Eigen::HouseholderQR<Eigen::MatrixXd>(hinf::test::random_matrix(seed + 1, n, n)).householderQ();
  const Eigen::VectorXd s =
      (hinf::test::random_matrix(seed + 2, n, 1).col(0).array() * std::log(2.0)).exp();
  return Q1 * s.asDiagonal() * Q2;
}

double rel_diff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / b.norm();
}

TEST(GoldenCheck, AcceptsASimilarityTransformOfTheGolden) {
  TempDir dir;
  const GainsFile golden = hinf::runtime_yaml::load_gains_file(kGolden);
  ASSERT_TRUE(golden.gamma.has_value());
  const Eigen::MatrixXd T = well_conditioned(20261126, golden.A_F.rows());
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(T);
  const double cond = svd.singularValues()(0) / svd.singularValues().tail(1)(0);
  ASSERT_LT(cond, 5.0);
  ASSERT_GT(cond, 1.5);  // not (nearly) a multiple of an orthogonal matrix
  const Eigen::MatrixXd Tinv = T.inverse();
  GainsFile t = golden;  // gamma, config_sha256 kept
  t.A_F = T * golden.A_F * Tinv;
  t.B_F = T * golden.B_F;
  t.C_F = golden.C_F * Tinv;
  // The realisation really differs, entry by entry.
  EXPECT_GT(rel_diff(t.A_F, golden.A_F), 0.1);
  EXPECT_GT(rel_diff(t.B_F, golden.B_F), 0.1);
  EXPECT_GT(rel_diff(t.C_F, golden.C_F), 0.1);
  write_gains(dir / "transformed.yaml", t);
  const auto r = synth("check " + kConfig + " --golden " + (dir / "transformed.yaml"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("same"), std::string::npos);
}

TEST(GoldenCheck, RejectsBFChangedByOnePercent) {
  TempDir dir;
  GainsFile g = hinf::runtime_yaml::load_gains_file(kGolden);
  g.B_F *= 1.01;  // the transfer function C_F (zI - A_F)^-1 B_F changes by exactly 1%
  write_gains(dir / "bf.yaml", g);
  const auto r = synth("check " + kConfig + " --golden " + (dir / "bf.yaml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(std::regex_search(r.output, std::regex("filter:.*CHANGED"))) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex("gamma:.*ok"))) << r.output;
  // The reported relative difference is the 1% put in (H-inf norm of 0.01 T / norm of T).
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(= ([0-9.eE+-]+) \(transfer)")));
  EXPECT_NEAR(std::stod(m[1]), 0.01 / 1.01, 1e-4);
}

TEST(GoldenCheck, RejectsGammaChangedByOnePercent) {
  TempDir dir;
  for (const double factor : {1.01, 0.99}) {
    GainsFile g = hinf::runtime_yaml::load_gains_file(kGolden);
    *g.gamma *= factor;
    write_gains(dir / "gamma.yaml", g);
    const auto r = synth("check " + kConfig + " --golden " + (dir / "gamma.yaml"));
    EXPECT_EQ(r.exit_code, 1) << factor;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("gamma:.*CHANGED"))) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("filter:.*ok"))) << r.output;
  }
}

TEST(GoldenCheck, RtolWidensTheTolerance) {
  // The same 1% change of B_F is accepted with --rtol 0.02 and refused with --rtol 0.005.
  TempDir dir;
  GainsFile g = hinf::runtime_yaml::load_gains_file(kGolden);
  g.B_F *= 1.01;
  write_gains(dir / "bf.yaml", g);
  EXPECT_EQ(synth("check " + kConfig + " --golden " + (dir / "bf.yaml") + " --rtol 0.02").exit_code, 0);
  EXPECT_EQ(synth("check " + kConfig + " --golden " + (dir / "bf.yaml") + " --rtol 0.005").exit_code, 1);
}

TEST(GoldenCheck, BadInputExits2) {
  TempDir dir;
  GainsFile g = hinf::runtime_yaml::load_gains_file(kGolden);
  g.gamma.reset();  // a golden file must state gamma
  write_gains(dir / "nogamma.yaml", g);
  EXPECT_EQ(synth("check " + kConfig + " --golden " + (dir / "nogamma.yaml")).exit_code, 2);
  EXPECT_EQ(synth("check " + kConfig + " --golden " + (dir / "missing.yaml")).exit_code, 2);
}

// docs/maths.md [D14]: a golden check must not break across platforms. Another platform (BLAS,
// MUMPS, compiler) perturbs the computation at the rounding level; the closest portable
// stand-in is a config with one coefficient moved by one ulp (a relative change of 1e-16,
// far below anything physical). `check` against the unchanged golden must still say
// "same" at its default rtol: gamma and the filter's transfer function must not move by
// more than 1e-6 for a 1e-16 change of the data.
class GoldenCheckUlp : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenCheckUlp, OneUlpChangeOfThePlantStillPasses) {
  const std::string stem = GetParam();
  TempDir dir;
  std::string text = hinf::test::read_text(kSource + "/configs/" + stem + ".yaml");
  // The first entry of B, written with the next double above it.
  const bool hill = text.find("\nhill:") != std::string::npos || text.rfind("hill:", 0) == 0;
  const std::string from = hill ? "B: {diag: [0.05," : "- [0.10]";
  const std::string to = hill ? "B: {diag: [0.050000000000000010," : "- [0.10000000000000002]";
  ASSERT_EQ(std::strtod(hill ? "0.050000000000000010" : "0.10000000000000002", nullptr),
            std::nextafter(hill ? 0.05 : 0.10, 1.0));
  const auto pos = text.find(from);
  ASSERT_NE(pos, std::string::npos) << stem;
  text.replace(pos, from.size(), to);
  hinf::test::write_text(dir / (stem + ".yaml"), text);
  const auto r = synth("check " + (dir / (stem + ".yaml")) + " --golden " + kSource +
                       "/tests/golden/" + stem + ".yaml");
  EXPECT_EQ(r.exit_code, 0) << stem << ": a 1-ulp change of B changes the synthesised filter";
}

INSTANTIATE_TEST_SUITE_P(ShippedConfigs, GoldenCheckUlp,
                         ::testing::Values("example-matrices", "paper-dbar0.05", "paper-dbar1"),
                         [](const ::testing::TestParamInfo<const char*>& i) {
                           std::string s = i.param;
                           for (auto& c : s)
                             if (c == '-' || c == '.') c = '_';
                           return s;
                         });

// Controller files (docs/maths.md §26): the golden check and verify of configs/tumbling-hold.yaml.
const std::string kControllerConfig = kSource + "/configs/tumbling-hold.yaml";
const std::string kControllerGolden = kSource + "/tests/golden/tumbling-hold.yaml";

// A golden controller file with its gamma line replaced by `gamma`.
std::string controller_with_gamma(const TempDir& dir, double gamma) {
  std::string text = hinf::test::read_text(kControllerGolden);
  const auto at = text.find("\ngamma: ");
  const auto end = text.find('\n', at + 1);
  char line[64];
  std::snprintf(line, sizeof line, "\ngamma: %.17g", gamma);
  text.replace(at, end - at, line);
  const std::string path = dir / "controller.yaml";
  hinf::test::write_text(path, text);
  return path;
}

TEST(ControllerGolden, SameWhenUnchangedAndAfterAOneUlpChangeOfTheMass) {
  EXPECT_EQ(synth("check " + kControllerConfig + " --golden " + kControllerGolden).exit_code, 0);
  TempDir dir;
  std::string text = hinf::test::read_text(kControllerConfig);
  const std::string from = "servicer_mass: 500 ", to = "servicer_mass: 500.00000000000006 ";
  ASSERT_EQ(std::strtod("500.00000000000006", nullptr), std::nextafter(500.0, 1000.0));
  const auto pos = text.find(from);
  ASSERT_NE(pos, std::string::npos);
  text.replace(pos, from.size(), to);
  hinf::test::write_text(dir / "tumbling-hold.yaml", text);
  EXPECT_EQ(synth("check " + (dir / "tumbling-hold.yaml") + " --golden " + kControllerGolden).exit_code, 0);
}

TEST(ControllerGolden, ChangedGammaOrControllerFails) {
  TempDir dir;
  // the golden γ moved by 1 %: CHANGED
  const auto r = synth("check " + kControllerConfig + " --golden " + controller_with_gamma(dir, 0.0632017 * 1.01));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("CHANGED"), std::string::npos) << r.output;
  // another design's controller (integral action, 9 states) against this config: CHANGED
  const auto other = synth("check " + kControllerConfig + " --golden " + kSource + "/tests/golden/tumbling-hold-integral.yaml");
  EXPECT_EQ(other.exit_code, 1) << other.output;
}

TEST(ControllerVerify, HoldsForTheGoldenAndFailsAnOverstatedGamma) {
  EXPECT_EQ(synth("verify " + kControllerConfig + " " + kControllerGolden).exit_code, 0);
  TempDir dir;
  const auto r = synth("verify " + kControllerConfig + " " + controller_with_gamma(dir, 0.0632017 * 0.98));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("NOT verified: the closed loop's norm is 0.0632016"), std::string::npos) << r.output;
}

// `verify CONFIG GAINS` exits 0 when the file's gamma holds for its filter, 1 if not.
// "verify fails a gamma overstated by 2%" (the issue) is read as: the *performance* is
// overstated, i.e. the file claims a bound 2% BELOW what the filter is certified to
// achieve (a smaller gamma is a stronger claim). Such a file must fail. A file claiming
// 2% ABOVE (a weaker, overly modest claim) states something true and must pass.
TEST(Verify, SolvedGainsPassStrongerClaimFailsWeakerClaimPasses) {
  TempDir dir;
  ASSERT_EQ(synth("solve " + kConfig + " -o " + (dir / "solved.yaml")).exit_code, 0);
  EXPECT_EQ(synth("verify " + kConfig + " " + (dir / "solved.yaml")).exit_code, 0);
  const GainsFile solved = hinf::runtime_yaml::load_gains_file(dir / "solved.yaml");
  ASSERT_TRUE(solved.gamma.has_value());
  GainsFile g = solved;
  *g.gamma = *solved.gamma * 0.98;  // performance overstated by 2%
  write_gains(dir / "overstated.yaml", g);
  const auto r = synth("verify " + kConfig + " " + (dir / "overstated.yaml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("NOT verified"), std::string::npos);
  *g.gamma = *solved.gamma * 1.02;  // weaker claim
  write_gains(dir / "modest.yaml", g);
  EXPECT_EQ(synth("verify " + kConfig + " " + (dir / "modest.yaml")).exit_code, 0);
}

// The paper's published filter (configs/paper-published-gains.yaml, no gamma) with a
// claim written in. No filter can beat the optimal gamma of Corollary 1 (the analysis
// LMI of a fixed full-order filter is the synthesis LMI at that point), so a claim 1%
// below the golden optimum must be refused; the printed "bound actually achieved" is
// what the published filter really guarantees (recorded in the test log).
TEST(Verify, PaperPublishedGainsCannotBeatTheOptimum) {
  TempDir dir;
  const GainsFile golden = hinf::runtime_yaml::load_gains_file(kGolden);
  GainsFile published =
      hinf::runtime_yaml::load_gains_file(kSource + "/configs/paper-published-gains.yaml");
  ASSERT_FALSE(published.gamma.has_value());
  published.gamma = *golden.gamma * 0.99;
  write_gains(dir / "published.yaml", published);
  const auto r = synth("verify " + kConfig + " " + (dir / "published.yaml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("NOT verified"), std::string::npos);
}

std::string without_timing(const std::string& text, bool* had_timing) {
  std::istringstream in(text);
  std::string line, out;
  bool skipping = false;
  *had_timing = false;
  while (std::getline(in, line)) {
    const bool top_level = !line.empty() && line[0] != ' ' && line[0] != '#' && line[0] != '-';
    if (top_level) skipping = line.rfind("timing:", 0) == 0;
    if (skipping) {
      *had_timing = true;
      continue;
    }
    out += line + "\n";
  }
  return out;
}

TEST(Solve, TwoRunsAreByteIdenticalApartFromTiming) {
  TempDir dir;
  for (const std::string cfg : {"example-matrices", "paper-dbar0.05"}) {
    const std::string config = kSource + "/configs/" + cfg + ".yaml";
    ASSERT_EQ(synth("solve " + config + " -o " + (dir / "a.yaml")).exit_code, 0);
    ASSERT_EQ(synth("solve " + config + " -o " + (dir / "b.yaml")).exit_code, 0);
    bool ta = false, tb = false;
    const std::string a = without_timing(hinf::test::read_text(dir / "a.yaml"), &ta);
    const std::string b = without_timing(hinf::test::read_text(dir / "b.yaml"), &tb);
    EXPECT_TRUE(ta && tb) << "no timing: section";
    EXPECT_NE(a.find("A_F"), std::string::npos);
    EXPECT_NE(a.find("certificate:"), std::string::npos);  // the rest is compared, not cut
    EXPECT_EQ(a, b) << cfg;
  }
}

}  // namespace
