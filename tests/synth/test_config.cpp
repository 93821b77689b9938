// The strict config reader (docs/file-formats.md): bad configs are refused with
// Error(InvalidInput) and a message naming the key path / dimension / value;
// good configs give the documented plant and settings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>

#include "hinf/common/suggest.hpp"
#include "config/sha256.hpp"  // private to synth (hinf_synth_private)
#include "hinf/common/number_text.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/common/error.hpp"

namespace {

using hinf::Error;
using hinf::ErrorCode;
using hinf::synth::parse_config;

const std::string kSource = std::string(HINF_SOURCE_DIR);

const char* const kSystem =
    "system:\n"
    "  A: [[0.5, 0.1], [0, 0.4]]\n"
    "  B: [[1], [0]]\n"
    "  C: [[1, 0]]\n"
    "  D: [[0.1]]\n"
    "  L: [[1, 0], [0, 1]]\n";

std::string hill_with(const std::string& extra_lines, const std::string& drop = "") {
  std::string lines[] = {"  orbital_rate: 7.2722e-5\n", "  chaser_mass: 1000\n",
                         "  sample_time: 0.1\n", "  delta_bar: 0.05\n",
                         "  B: {diag: [0.05, 0.05, 0.05, 0.001, 0.001, 0.001]}\n",
                         "  D: {diag: [0.1, 0.1, 0.1]}\n"};
  std::string text = "hill:\n";
  for (const auto& l : lines)
    if (drop.empty() || l.find(drop) == std::string::npos) text += l;
  return text + extra_lines;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Expects Error(InvalidInput) whose message contains every fragment.
void expect_invalid(const std::string& yaml, std::initializer_list<std::string> fragments) {
  try {
    parse_config(yaml, "bad.yaml");
    ADD_FAILURE() << "accepted:\n" << yaml;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    const std::string msg = e.what();
    for (const auto& f : fragments)
      EXPECT_NE(msg.find(f), std::string::npos)
          << "message\n  " << msg << "\nlacks\n  " << f << "\nfor config:\n" << yaml;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what() << "\nfor config:\n" << yaml;
  }
}

void expect_invalid_file(const std::string& path, std::initializer_list<std::string> fragments) {
  try {
    hinf::synth::load_config(path);
    ADD_FAILURE() << "accepted " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    const std::string msg = e.what();
    for (const auto& f : fragments)
      EXPECT_NE(msg.find(f), std::string::npos) << "message\n  " << msg << "\nlacks\n  " << f;
  }
}

// ---------------------------------------------------------------- good configs

TEST(Config, BaseSystemConfigParses) {
  const auto cfg = parse_config(kSystem, "ok.yaml");
  EXPECT_EQ(cfg.plant.n(), 2);
  EXPECT_EQ(cfg.plant.p(), 1);
  EXPECT_EQ(cfg.plant.m(), 1);
  EXPECT_EQ(cfg.plant.q(), 1);
  EXPECT_EQ(cfg.plant.l(), 2);
  EXPECT_FALSE(cfg.plant.uncertain());
  EXPECT_FALSE(cfg.hill.has_value());
  EXPECT_EQ(cfg.plant.A(0, 1), 0.1);
  EXPECT_EQ(cfg.plant.A(1, 0), 0.0);
  EXPECT_EQ(cfg.path, "ok.yaml");
  EXPECT_EQ(cfg.sha256, hinf::synth::sha256_hex(kSystem));
}

TEST(Config, ExampleMatricesConfigIsRobustlySchurStable) {
  const auto cfg = hinf::synth::load_config(kSource + "/configs/example-matrices.yaml");
  const auto& P = cfg.plant;
  ASSERT_EQ(P.n(), 2);
  ASSERT_TRUE(P.uncertain());
  EXPECT_EQ(P.j(), 1);
  EXPECT_EQ(P.k(), 1);
  // The file's comment: spectral radius sqrt(0.58), and in [sqrt(0.545), sqrt(0.615)]
  // for A + H f E, |f| <= 1 (complex pair, |λ|² = det).
  EXPECT_NEAR(P.A.eigenvalues().cwiseAbs().maxCoeff(), std::sqrt(0.58), 1e-15);
  for (double f : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
    const Eigen::MatrixXd Af = P.A + P.H * f * P.E;
    EXPECT_NEAR(Af.eigenvalues().cwiseAbs().maxCoeff(), std::sqrt(0.58 + 0.035 * f), 1e-15);
  }
}

TEST(Config, EveryScalarFormAndEverySolverFieldIsRead) {
  const std::string yaml = std::string(kSystem) +
                           "uncertainty:\n  H: {diag: [0.1, 0.2]}\n  E: [[1, 0], [0, 1]]\n"
                           "solver:\n"
                           "  lmi_margin: 1e-7\n"
                           "  relative_gap_tol: 1.5E-9\n"
                           "  barrier_growth: 10\n"
                           "  feasibility_radius: 1.0e+6\n"
                           "  max_newton_per_centering: 40\n"
                           "  max_iterations: 300\n"
                           "  time_limit_s: 12.5\n"
                           "  max_memory_mb: 2048\n"
                           "  gamma_backoff: 0.01\n"
                           "  stability_samples: 0\n"
                           "  seed: 4000000000\n"
                           "  verbose: true\n";
  const auto cfg = parse_config(yaml, "s.yaml");
  const auto& s = cfg.settings;
  EXPECT_EQ(s.solver.lmi_margin, 1e-7);
  EXPECT_EQ(s.solver.relative_gap_tol, 1.5e-9);
  EXPECT_EQ(s.solver.barrier_growth, 10.0);
  EXPECT_EQ(s.solver.feasibility_radius, 1e6);
  EXPECT_EQ(s.solver.max_newton_per_centering, 40);
  EXPECT_EQ(s.solver.max_iterations, 300);
  EXPECT_EQ(s.solver.time_limit_s, 12.5);
  EXPECT_EQ(s.max_memory_mb, 2048.0);
  EXPECT_EQ(s.gamma_backoff, 0.01);
  EXPECT_EQ(s.stability_samples, 0);
  EXPECT_EQ(s.seed, 4000000000u);
  EXPECT_TRUE(s.verbose);
  EXPECT_EQ(cfg.plant.H(1, 1), 0.2);
  EXPECT_EQ(cfg.plant.H(0, 1), 0.0);
}

TEST(Config, OrbitalPeriodGivesTwoPiOverPeriod) {
  std::string yaml = hill_with("  orbital_period: 86400\n  discretisation: zoh\n", "orbital_rate");
  const auto cfg = parse_config(yaml, "p.yaml");
  ASSERT_TRUE(cfg.hill.has_value());
  EXPECT_DOUBLE_EQ(cfg.hill->orbital_rate, 2 * M_PI / 86400);
  EXPECT_EQ(cfg.hill->discretisation, hinf::models::Discretisation::ZeroOrderHold);
  EXPECT_TRUE(cfg.hill->K.size() == 0);  // absent K = no control
}

TEST(Config, Sha256IsOfTheExactFileBytes) {
  const std::string path = kSource + "/configs/paper-dbar0.05.yaml";
  const auto cfg = hinf::synth::load_config(path);
  EXPECT_EQ(cfg.path, path);
  EXPECT_EQ(cfg.sha256, hinf::synth::sha256_hex(read_bytes(path)));
  EXPECT_EQ(cfg.sha256.size(), 64u);
  // a comment changes the bytes, hence the hash, not the plant
  const auto other = parse_config(read_bytes(path) + "# comment\n", "x.yaml");
  EXPECT_NE(other.sha256, cfg.sha256);
  EXPECT_EQ(other.plant.A, cfg.plant.A);
}

// FIPS 180-4 / NIST example vectors.
TEST(NumberText, ShortestRoundTripTextWithoutNeedlessExponents) {
  using hinf::number_text;
  EXPECT_EQ(number_text(10), "10");
  EXPECT_EQ(number_text(-5), "-5");
  EXPECT_EQ(number_text(0.1), "0.1");
  EXPECT_EQ(number_text(-0.0001), "-0.0001");
  EXPECT_EQ(number_text(1e-15), "1e-15");
  EXPECT_EQ(number_text(7.2722e-5), "7.2722e-5");
  EXPECT_EQ(number_text(1e20), "1e20");
  EXPECT_EQ(number_text(123456.5), "123456.5");
  EXPECT_EQ(number_text(0.1 + 0.2), "0.30000000000000004");
  for (double v : {M_PI, -1.0 / 3, 6.02214076e23, 4.9e-324, 1.7976931348623157e308})
    EXPECT_EQ(std::strtod(number_text(v).c_str(), nullptr), v) << number_text(v);
}

TEST(Sha256, FipsTestVectors) {
  using hinf::synth::sha256_hex;
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(DidYouMean, EditDistanceAndSuggestions) {
  using hinf::closest_match;
  using hinf::edit_distance;
  EXPECT_EQ(edit_distance("sampel_time", "sample_time"), 1);  // one transposition
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
  EXPECT_EQ(edit_distance("", "abc"), 3);
  EXPECT_EQ(edit_distance("Lmi_Margin", "lmi_margin"), 0);  // case-insensitive
  EXPECT_EQ(closest_match("sytem", {"system", "hill"}), "system");
  EXPECT_FALSE(closest_match("banana", {"system", "hill"}).has_value());
  EXPECT_EQ(closest_match("diagonal", {"diag"}), "diag");  // extension of a key
  EXPECT_FALSE(closest_match("di", {"diag_x"}).has_value());  // too short to be a prefix hint
}

// ---------------------------------------------------------------- bad configs

TEST(BadConfig, UnknownKeysAreRefusedWithPathAndSuggestion) {
  expect_invalid(std::string("sytem:\n") + (kSystem + 8),
                 {"unknown key 'sytem'", "did you mean 'system'?"});
  expect_invalid(hill_with("  sampel_time: 0.2\n", "sample_time"),
                 {"unknown key 'hill.sampel_time'", "(did you mean 'sample_time'?)", "bad.yaml:7:3"});
  expect_invalid(std::string(kSystem) + "solver:\n  lmi_margn: 1e-9\n",
                 {"unknown key 'solver.lmi_margn'", "did you mean 'lmi_margin'?"});
  expect_invalid(std::string(kSystem) + "solver:\n  tolerance: 1e-9\n",
                 {"unknown key 'solver.tolerance'", "allowed here:", "relative_gap_tol"});
  expect_invalid(hill_with("  C: {diagonal: [1, 1, 1]}\n"),
                 {"unknown key 'hill.C.diagonal'", "did you mean 'diag'?"});
  expect_invalid(std::string(kSystem) + "uncertainty:\n  H: [[1], [0]]\n  F: [[1, 0]]\n",
                 {"unknown key 'uncertainty.F'"});
}

TEST(BadConfig, UnknownKeyInFileGivesFileLineColumn) {
  expect_invalid_file(kSource + "/tests/data/bad-configs/unknown-key.yaml",
                      {"unknown-key.yaml:5:3", "unknown key 'hill.sampel_time'",
                       "did you mean 'sample_time'?"});
}

TEST(BadConfig, ExactlyOneOfSystemAndHill) {
  expect_invalid(std::string(kSystem) + hill_with(""), {"both 'system' and 'hill'"});
  expect_invalid("solver:\n  lmi_margin: 1e-9\n", {"neither 'system' nor 'hill'"});
  expect_invalid(hill_with("") + "uncertainty:\n  H: [[1]]\n  E: [[1]]\n",
                 {"'uncertainty' is only allowed with 'system'"});
}

TEST(BadConfig, UncertaintyNeedsBothHAndE) {
  expect_invalid(std::string(kSystem) + "uncertainty:\n  H: [[1], [0]]\n",
                 {"missing key 'uncertainty.E'"});
  expect_invalid(std::string(kSystem) + "uncertainty:\n  E: [[1, 0]]\n",
                 {"missing key 'uncertainty.H'"});
  expect_invalid(std::string(kSystem) + "uncertainty:\n  H: [[1], [0], [0]]\n  E: [[1, 0]]\n",
                 {"uncertainty.H: expected 2 rows (n from A), got 3"});
  expect_invalid(std::string(kSystem) + "uncertainty:\n  H: [[1], [0]]\n  E: [[1, 0, 0]]\n",
                 {"uncertainty.E: expected 2 columns (n from A), got 3"});
}

TEST(BadConfig, MissingRequiredKeys) {
  expect_invalid("system:\n  A: [[0.5]]\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n",
                 {"missing key 'system.L'"});
  expect_invalid(hill_with("", "chaser_mass"), {"missing key 'hill.chaser_mass'", "kg"});
  expect_invalid(hill_with("", "orbital_rate"), {"missing key 'hill.orbital_rate'"});
  expect_invalid(hill_with("  orbital_period: 86400\n"),
                 {"exactly one of 'hill.orbital_rate'", "'hill.orbital_period'"});
}

// The Hill builder names its fields; the reader re-keys them to hill.<field> at the
// key's file:line:col (the values that overflowed the discrete model, issue 13).
TEST(BadConfig, HillValuesNamedByTheirKeys) {
  expect_invalid(hill_with("  chaser_mass: 4.9e-324\n", "chaser_mass"),
                 {"bad.yaml:", "hill.chaser_mass = 5e-324: too small"});
  expect_invalid(hill_with("  sample_time: 1e300\n  discretisation: zoh\n", "sample_time"),
                 {"hill.sample_time = 1e300: the discrete Hill model"});
}

TEST(BadConfig, MatrixShapes) {
  expect_invalid_file(kSource + "/tests/data/bad-configs/ragged.yaml",
                      {"ragged.yaml:5:7", "system.A: ragged rows: row 2 has 2 entries, row 1 has 3"});
  expect_invalid("system:\n  A: [[0.5, 0.1]]\n  B: [[1]]\n  C: [[1, 0]]\n  D: [[1]]\n  L: [[1, 0]]\n",
                 {"system.A: must be square", "1x2"});
  expect_invalid("system:\n  A: [[0.5, 0.1], [0, 0.4]]\n  B: [[1], [0], [0]]\n  C: [[1, 0]]\n"
                 "  D: [[0.1]]\n  L: [[1, 0]]\n",
                 {"system.B: expected 2 rows (n from A), got 3", "bad.yaml:3:6"});
  expect_invalid("system:\n  A: [[0.5, 0.1], [0, 0.4]]\n  B: [[1], [0]]\n  C: [[1, 0, 0]]\n"
                 "  D: [[0.1]]\n  L: [[1, 0]]\n",
                 {"system.C: expected 2 columns (n from A), got 3"});
  expect_invalid("system:\n  A: [[0.5, 0.1], [0, 0.4]]\n  B: [[1], [0]]\n  C: [[1, 0]]\n"
                 "  D: [[0.1], [0.1]]\n  L: [[1, 0]]\n",
                 {"system.D: expected 1 rows (m from C), got 2"});
  expect_invalid("system:\n  A: [[0.5, 0.1], [0, 0.4]]\n  B: [[1], [0]]\n  C: [[1, 0]]\n"
                 "  D: [[0.1]]\n  L: {diag: [1, 1, 1]}\n",
                 {"system.L: expected 2 columns (n from A), got 3"});
  expect_invalid(std::string(kSystem) + "  B: [[1], [0]]\n", {"duplicate key 'system.B'"});
}

TEST(BadConfig, EmptyAndMalformedMatrices) {
  expect_invalid("system:\n  A: []\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A: empty matrix"});
  expect_invalid("system:\n  A: [[]]\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A: row 1 is empty"});
  expect_invalid("system:\n  A: [0.5, 0.1]\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A: row 1 is the scalar '0.5', not a list"});
  expect_invalid("system:\n  A: 0.5\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A: expected a matrix", "the scalar '0.5'"});
  expect_invalid("system:\n  A:\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A: expected a matrix", "an empty value"});
  expect_invalid(hill_with("  L: {diag: []}\n"), {"hill.L.diag: empty list"});
  expect_invalid(hill_with("  C: {}\n"), {"'hill.C' is an empty map"});
}

TEST(BadConfig, NonNumericAndNonFiniteEntries) {
  expect_invalid("system:\n  A: [[0.5, x1]]\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A entry (1, 2) = 'x1': not a number"});
  expect_invalid("system:\n  A: [[0.5, .nan], [0, 1]]\n  B: [[1], [0]]\n  C: [[1, 0]]\n"
                 "  D: [[1]]\n  L: [[1, 0]]\n",
                 {"system.A entry (1, 2) = .nan: not finite"});
  expect_invalid(hill_with("  K: [[0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, -.inf], [0, 0, 0, 0, 0, 0]]\n"),
                 {"hill.K entry (2, 6) = -.inf: not finite"});
  expect_invalid(hill_with("  C: [[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, \"0\"]]\n"),
                 {"hill.C entry (2, 6)", "quoted string \"0\""});
  expect_invalid("system:\n  A: [[0x10]]\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A entry (1, 1) = '0x10': not a number"});
  expect_invalid("system:\n  A: [[1e999]]\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A entry (1, 1) = 1e999: out of the range of a double"});
  expect_invalid("system:\n  A: [[[0.5]]]\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n",
                 {"system.A entry (1, 1): expected a number, got a list"});
}

TEST(BadConfig, AbsurdPhysicalValues) {
  expect_invalid(hill_with("  chaser_mass: -5\n", "chaser_mass"),
                 {"hill.chaser_mass = -5: must be finite and > 0 (kg)"});
  expect_invalid(hill_with("  sample_time: 0\n", "sample_time"), {"hill.sample_time = 0"});
  expect_invalid(hill_with("  delta_bar: 10\n", "delta_bar"), {"hill.delta_bar = 10", "[0, 10)"});
  expect_invalid(hill_with("  delta_bar: -0.01\n", "delta_bar"), {"hill.delta_bar = -0.01"});
  expect_invalid(hill_with("  orbital_rate: 0\n", "orbital_rate"), {"hill.orbital_rate = 0"});
  expect_invalid(hill_with("  orbital_rate: .inf\n", "orbital_rate"), {"hill.orbital_rate = inf"});
  expect_invalid(hill_with("  orbital_period: -1\n", "orbital_rate"),
                 {"hill.orbital_period = -1: must be finite and > 0 (s)"});
  expect_invalid(hill_with("  chaser_mass: heavy\n", "chaser_mass"),
                 {"hill.chaser_mass = 'heavy': not a number"});
  expect_invalid(hill_with("  K: [[1, 2, 3, 4, 5, 6], [1, 2, 3, 4, 5, 6]]\n"),
                 {"hill.K: expected 3x6", "got 2x6"});
  expect_invalid(hill_with("  D: {diag: [0.1, 0.1]}\n", "  D:"),
                 {"hill.D: expected 3 rows (m from C)", "got 2x2"});
  expect_invalid(hill_with("  discretisation: eular\n"),
                 {"hill.discretisation = 'eular'", "did you mean 'euler'?"});
}

TEST(BadConfig, SolverSettingsOutOfRange) {
  const std::string base = std::string(kSystem) + "solver:\n";
  expect_invalid(base + "  lmi_margin: -1\n", {"solver.lmi_margin = -1: must be > 0", "bad.yaml:8:15"});
  expect_invalid(base + "  lmi_margin: 1e-15\n", {"solver.lmi_margin = 1e-15", "below solver tolerance"});
  expect_invalid(base + "  lmi_margin: 0.1\n", {"solver.lmi_margin = 0.1", "<= 0.01"});
  expect_invalid(base + "  relative_gap_tol: 1\n", {"solver.relative_gap_tol = 1", "[1e-12, 0.01]"});
  expect_invalid(base + "  relative_gap_tol: 1e-13\n", {"solver.relative_gap_tol = 1e-13"});
  expect_invalid(base + "  barrier_growth: 1.2\n", {"solver.barrier_growth = 1.2: must be > 1.5"});
  expect_invalid(base + "  max_iterations: 1.5\n", {"solver.max_iterations = '1.5': must be an integer"});
  expect_invalid(base + "  max_iterations: 0\n", {"solver.max_iterations = 0"});
  expect_invalid(base + "  time_limit_s: .nan\n", {"solver.time_limit_s = nan: must be finite"});
  expect_invalid(base + "  max_memory_mb: 10\n", {"solver.max_memory_mb = 10: must be in [64, 1048576] (MiB)"});
  expect_invalid(base + "  gamma_backoff: -0.1\n", {"solver.gamma_backoff = -0.1"});
  expect_invalid(base + "  seed: -1\n", {"solver.seed = '-1': must be a non-negative integer"});
  expect_invalid(base + "  verbose: maybe\n", {"solver.verbose = 'maybe': must be true or false"});
  expect_invalid(base + "  max_iterations: 99999999999\n", {"solver.max_iterations = 99999999999: out of the range"});
  expect_invalid(base, {"'solver' is empty"});
}

TEST(BadConfig, SyntaxErrorsGiveFileLineColumn) {
  expect_invalid_file(kSource + "/tests/data/bad-configs/syntax-error.yaml",
                      {"syntax-error.yaml:5:", "YAML syntax error"});
  expect_invalid("system:\n  A: [[1]\n\tB: 2\n", {"bad.yaml:", "YAML syntax error"});
}

TEST(BadConfig, EmptyMissingAndNonMapInputs) {
  expect_invalid_file(kSource + "/tests/data/bad-configs/empty.yaml", {"empty.yaml", "empty config"});
  expect_invalid("", {"bad.yaml: empty config"});
  expect_invalid("# only a comment\n", {"bad.yaml: empty config"});
  expect_invalid_file(kSource + "/tests/data/bad-configs/no-such-file.yaml",
                      {"cannot read config '", "no-such-file.yaml", "No such file"});
  expect_invalid_file(kSource + "/tests/data/bad-configs",
                      {"bad-configs", "is a directory"});
  expect_invalid("- system\n- hill\n", {"the top level must be a map", "a list"});
  expect_invalid("just text\n", {"the top level must be a map", "the scalar 'just text'"});
  expect_invalid(std::string(kSystem) + "---\n" + kSystem, {"2 YAML documents"});
  expect_invalid("? [a, b]\n: 1\n", {"keys must be names"});
}

TEST(BadConfig, DeepNestingIsAnErrorNotACrash) {
  const std::string deep = "system:\n  A: " + std::string(100000, '[') + std::string(100000, ']') + "\n";
  try {
    parse_config(deep, "deep.yaml");
    ADD_FAILURE() << "accepted a 100000-deep matrix";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("deep.yaml"), std::string::npos) << e.what();
  }
}

}  // namespace
