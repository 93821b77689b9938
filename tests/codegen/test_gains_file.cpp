// The gains-file reader (runtime/yaml): accepted files and the messages of
// rejected ones (file, position, key path, expected and actual sizes).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "codegen_test_support.hpp"
#include "hinf/common/error.hpp"
#include "hinf/runtime_yaml/controller_file.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/runtime_yaml/lti_filter_from_gains.hpp"

namespace {

using hinf::Error;
using hinf::ErrorCode;
using hinf::runtime_yaml::load_gains_file;
using hinf::runtime_yaml::parse_gains_yaml;

const char* const kGood = R"(format: hinf-gains/1
tool: hinf-synth 0.1.0
config_sha256: 0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef
dimensions: {n: 2, m: 1, l: 1}
gamma: 1.5
gamma_squared: 2.25
filter:
  A_F: [[0.5, 0.1], [-0.2, 0.3]]
  B_F: [[1], [2e-3]]
  C_F: [[1.0, -1.0]]
certificate: {lmi_min_eig: -1e-9, anything: [1, 2]}
solver: {status: solved}
timing: {total_s: 1.5}
)";

// Returns the message of the Error(InvalidInput) thrown for `text` (fails if none).
std::string error_for(const std::string& text) {
  try {
    parse_gains_yaml(text, "g.yaml");
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) s.replace(pos, from.size(), to);
  return s;
}

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

TEST(GainsFile, ReadsAllFields) {
  const auto g = parse_gains_yaml(kGood, "g.yaml");
  ASSERT_EQ(g.A_F.rows(), 2);
  ASSERT_EQ(g.A_F.cols(), 2);
  ASSERT_EQ(g.B_F.rows(), 2);
  ASSERT_EQ(g.B_F.cols(), 1);
  ASSERT_EQ(g.C_F.rows(), 1);
  ASSERT_EQ(g.C_F.cols(), 2);
  EXPECT_EQ(g.A_F(1, 0), -0.2);
  EXPECT_EQ(g.B_F(1, 0), 2e-3);
  EXPECT_EQ(g.C_F(0, 1), -1.0);
  ASSERT_TRUE(g.gamma.has_value());
  EXPECT_EQ(*g.gamma, 1.5);
  EXPECT_EQ(g.tool, "hinf-synth 0.1.0");
  EXPECT_EQ(g.config_sha256.size(), 64u);
}

TEST(GainsFile, MinimalHandWrittenFile) {
  const auto g = parse_gains_yaml("format: hinf-gains/1\nfilter:\n  A_F: [[1]]\n  B_F: [[2]]\n"
                                  "  C_F: [[3]]\n",
                                  "min.yaml");
  EXPECT_EQ(g.A_F(0, 0), 1.0);
  EXPECT_FALSE(g.gamma.has_value());
  EXPECT_TRUE(g.config_sha256.empty());
  EXPECT_TRUE(g.tool.empty());
}

TEST(GainsFile, PaperGainsFile) {
  const auto g = load_gains_file(HINF_TEST_PAPER_GAINS);
  ASSERT_EQ(g.A_F.rows(), 6);
  ASSERT_EQ(g.B_F.cols(), 3);
  ASSERT_EQ(g.C_F.rows(), 6);
  // docs/maths.md (78)–(80): A_F(4,1) = −6.1302, B_F(5,2) = −6.0989, C_F(4,4) = −0.999960 (1-based).
  EXPECT_EQ(g.A_F(3, 0), -6.1302);
  EXPECT_EQ(g.B_F(4, 1), -6.0989);
  EXPECT_NEAR(g.C_F(3, 3), -0.99996, 1e-15);
}

TEST(GainsFile, FormatIsRequiredAndChecked) {
  auto msg = error_for(replace(kGood, "format: hinf-gains/1\n", ""));
  EXPECT_HAS(msg, "g.yaml");
  EXPECT_HAS(msg, "missing key 'format'");
  msg = error_for(replace(kGood, "hinf-gains/1", "hinf-gains/2"));
  EXPECT_HAS(msg, "g.yaml:1:");
  EXPECT_HAS(msg, "unsupported format 'hinf-gains/2'");
}

TEST(GainsFile, UnknownTopLevelKeyIsAnErrorWithSuggestion) {
  const auto msg = error_for(std::string(kGood) + "gamma_sqared: 3\n");
  EXPECT_HAS(msg, "g.yaml:14:");
  EXPECT_HAS(msg, "unknown key 'gamma_sqared'");
  EXPECT_HAS(msg, "did you mean 'gamma_squared'?");
}

TEST(GainsFile, DuplicateKeyIsAnError) {
  EXPECT_HAS(error_for(std::string(kGood) + "gamma: 2\n"), "g.yaml:14:1: duplicate key 'gamma'");
}

TEST(GainsFile, FilterKeys) {
  EXPECT_HAS(error_for("format: hinf-gains/1\n"), "missing key 'filter'");
  EXPECT_HAS(error_for(replace(kGood, "  C_F: [[1.0, -1.0]]\n", "")), "missing key 'filter.C_F'");
  EXPECT_HAS(error_for(replace(kGood, "  C_F:", "  D_F: [[1]]\n  C_F:")),
             "filter.D_F: only a filtered estimate (filter.estimate: filtered) has D_F");
  EXPECT_HAS(error_for(replace(kGood, "  C_F:", "  D_G: [[1]]\n  C_F:")), "unknown key 'filter.D_G'");
  EXPECT_HAS(error_for(replace(kGood, "  C_F: [[1.0, -1.0]]", "  C_F: {diag: [1, 1]}")),
             "filter.C_F: expected a matrix");
}

TEST(GainsFile, ShapesNameExpectedAndActualDimensions) {
  auto msg = error_for(replace(kGood, "A_F: [[0.5, 0.1], [-0.2, 0.3]]", "A_F: [[0.5, 0.1]]"));
  EXPECT_HAS(msg, "g.yaml:8:");
  EXPECT_HAS(msg, "filter.A_F: must be square (n x n), got 1x2");
  msg = error_for(replace(kGood, "B_F: [[1], [2e-3]]", "B_F: [[1], [2e-3], [3]]"));
  EXPECT_HAS(msg, "filter.B_F: expected 2 rows (n x m, n = 2 from filter.A_F), got 3x1");
  msg = error_for(replace(kGood, "C_F: [[1.0, -1.0]]", "C_F: [[1.0, -1.0, 2.0]]"));
  EXPECT_HAS(msg, "filter.C_F: expected 2 columns (l x n, n = 2 from filter.A_F), got 1x3");
  msg = error_for(replace(kGood, "A_F: [[0.5, 0.1], [-0.2, 0.3]]", "A_F: [[0.5, 0.1], [-0.2]]"));
  EXPECT_HAS(msg, "filter.A_F: ragged rows: row 2 has 1 entries, row 1 has 2");
  EXPECT_HAS(error_for(replace(kGood, "A_F: [[0.5, 0.1], [-0.2, 0.3]]", "A_F: []")),
             "filter.A_F: empty matrix");
  EXPECT_HAS(error_for(replace(kGood, "A_F: [[0.5, 0.1], [-0.2, 0.3]]", "A_F: [0.5, 0.1]")),
             "filter.A_F: row 1 is the scalar '0.5', not a list");
}

TEST(GainsFile, DimensionsMustAgreeWithTheMatrices) {
  const auto msg = error_for(replace(kGood, "{n: 2, m: 1, l: 1}", "{n: 2, m: 3, l: 1}"));
  EXPECT_HAS(msg, "g.yaml:4:");
  EXPECT_HAS(msg, "dimensions.m: declares 3 but the filter has 1 (columns of filter.B_F");
  EXPECT_HAS(error_for(replace(kGood, "{n: 2, m: 1, l: 1}", "{n: 2, m: 1, l: 1, p: 2}")),
             "unknown key 'dimensions.p'");
  EXPECT_HAS(error_for(replace(kGood, "{n: 2, m: 1, l: 1}", "{n: -2, m: 1, l: 1}")),
             "dimensions.n = -2: must be > 0");
  EXPECT_HAS(error_for(replace(kGood, "{n: 2, m: 1, l: 1}", "{n: two}")),
             "dimensions.n = 'two': must be an integer");
}

TEST(GainsFile, EntriesMustBeFiniteNumbers) {
  auto msg = error_for(replace(kGood, "[[1], [2e-3]]", "[[1], [abc]]"));
  EXPECT_HAS(msg, "g.yaml:9:");
  EXPECT_HAS(msg, "filter.B_F entry (2, 1) = 'abc': not a number");
  EXPECT_HAS(error_for(replace(kGood, "[[1], [2e-3]]", "[[1], [.nan]]")),
             "filter.B_F entry (2, 1) = .nan: not finite");
  EXPECT_HAS(error_for(replace(kGood, "[[1], [2e-3]]", "[[1], [-.inf]]")),
             "filter.B_F entry (2, 1) = -.inf: not finite");
  EXPECT_HAS(error_for(replace(kGood, "[[1], [2e-3]]", "[[1], [1e999]]")),
             "filter.B_F entry (2, 1) = 1e999: out of the range of a double");
  EXPECT_HAS(error_for(replace(kGood, "[[1], [2e-3]]", "[[1], [[2]]]")),
             "filter.B_F entry (2, 1): expected a number");
  EXPECT_HAS(error_for(replace(kGood, "[[1], [2e-3]]", "[[1], [\"2e-3\"]]")),
             "filter.B_F entry (2, 1): expected a number, got the quoted string \"2e-3\"");
}

TEST(GainsFile, OptionalScalarsAreChecked) {
  EXPECT_HAS(error_for(replace(kGood, "gamma: 1.5", "gamma: -1")), "gamma = -1: must be > 0");
  EXPECT_HAS(error_for(replace(kGood, "gamma: 1.5", "gamma: .inf")), "gamma = .inf: not finite");
  EXPECT_HAS(error_for(replace(kGood, "0123456789abcdef0123456789abcdef0123456789abcdef01234567"
                                      "89abcdef",
                               "xyz")),
             "config_sha256: expected 64 hexadecimal digits, got 'xyz'");
}

// A controller file's config_sha256 is read by the same rule as a gains file's (issue 34: any
// word was accepted).
TEST(ControllerFile, ConfigSha256MustBeSixtyFourHexDigits) {
  std::ifstream in(std::string(HINF_TEST_CONTROLLERS_DIR) + "/../../golden/tumbling-hold.yaml");
  std::stringstream text;
  text << in.rdbuf();
  const std::string good = text.str();
  ASSERT_NE(good.find("config_sha256: "), std::string::npos);
  EXPECT_NO_THROW(hinf::runtime_yaml::parse_controller_yaml(good, "k.yaml"));
  const std::size_t at = good.find("config_sha256: ") + std::string("config_sha256: ").size();
  const std::string bad = good.substr(0, at) + "xyz" + good.substr(good.find('\n', at));
  try {
    hinf::runtime_yaml::parse_controller_yaml(bad, "k.yaml");
    FAIL() << "accepted config_sha256: xyz";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("config_sha256: expected 64 hexadecimal digits, got 'xyz'"), std::string::npos)
        << e.what();
  }
}

TEST(GainsFile, NotAGainsFileAtAll) {
  EXPECT_HAS(error_for(""), "g.yaml: empty file");
  EXPECT_HAS(error_for("[1, 2]"), "the top level must be a map");
  EXPECT_HAS(error_for("format: [unclosed"), "g.yaml:");
  EXPECT_HAS(error_for("format: [unclosed"), "YAML syntax error");
}

TEST(GainsFile, LoadReportsUnreadableFiles) {
  hinf::test::TempDir dir;
  try {
    load_gains_file(dir / "missing.yaml");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_HAS(std::string(e.what()), dir / "missing.yaml");
    EXPECT_HAS(std::string(e.what()), "No such file");
  }
  try {
    load_gains_file(dir.path());
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_HAS(std::string(e.what()), "is a directory");
  }
  hinf::test::write_text(dir / "g.yaml", kGood);
  EXPECT_EQ(load_gains_file(dir / "g.yaml").A_F(0, 0), 0.5);
}

TEST(GainsFile, MakeLtiFilter) {
  const auto f = hinf::runtime_yaml::make_lti_filter(load_gains_file(HINF_TEST_PAPER_GAINS));
  EXPECT_EQ(f.n(), 6);
  EXPECT_EQ(f.m(), 3);
  EXPECT_EQ(f.l(), 6);
  // A_F = 1.5 is not Schur stable: reported as a gains-file error naming the source.
  const auto unstable = parse_gains_yaml(
      "format: hinf-gains/1\nfilter: {A_F: [[1.5]], B_F: [[1]], C_F: [[1]]}\n", "u.yaml");
  try {
    hinf::runtime_yaml::make_lti_filter(unstable, "u.yaml");
    ADD_FAILURE() << "unstable filter accepted";
  } catch (const Error& e) {
    EXPECT_HAS(std::string(e.what()), "u.yaml: filter: ");
    EXPECT_HAS(std::string(e.what()), "not Schur stable");
  }
}

// The loader builds the whole filter the file describes (issue: it once passed A_F, B_F, C_F
// only): a filtered estimate's z(k) = C_F x_F(k) + D_F y(k) and a known input's
// x_F(k+1) = A_F x_F + B_F y + G_F u. One state, x_F(0) = 0, y = 1, u = 2, by hand:
// z(0) = D_F = 0.75, x_F(1) = B_F + 2 G_F = 0.25 + 2·0.5 = 1.25, z(1) = C_F x_F(1) + D_F = 2·1.25 + 0.75.
TEST(GainsFile, MakeLtiFilterCarriesFeedthroughAndKnownInput) {
  const auto g = parse_gains_yaml(
      "format: hinf-gains/1\nfilter:\n  form: observer\n  estimate: filtered\n  A_F: [[0.5]]\n  B_F: [[0.25]]\n"
      "  C_F: [[2]]\n  K: [[0.25]]\n  M: [[0.1]]\n  D_F: [[0.75]]\n  G_F: [[0.5]]\n",
      "f.yaml");
  auto f = hinf::runtime_yaml::make_lti_filter(g, "f.yaml");
  EXPECT_EQ(f.r(), 1);
  const Eigen::VectorXd y = Eigen::VectorXd::Constant(1, 1.0), u = Eigen::VectorXd::Constant(1, 2.0);
  EXPECT_THROW(f.step(y), std::invalid_argument);  // a filter with a known input needs u
  EXPECT_EQ(f.step(y, u)(0), 0.75);
  EXPECT_EQ(f.step(y, u)(0), 2.0 * 1.25 + 0.75);
  // Without G_F the same file's filter steps on y alone and keeps its feedthrough.
  auto p = hinf::runtime_yaml::make_lti_filter(
      parse_gains_yaml("format: hinf-gains/1\nfilter:\n  form: observer\n  estimate: filtered\n  A_F: [[0.5]]\n"
                       "  B_F: [[0.25]]\n  C_F: [[2]]\n  K: [[0.25]]\n  M: [[0.1]]\n  D_F: [[0.75]]\n",
                       "p.yaml"));
  EXPECT_EQ(p.step(y)(0), 0.75);
}

}  // namespace

// The observer form (docs/maths.md (121)): filter.form, filter.K (required there and only
// there), filter.G_F and dimensions.r.
TEST(GainsFile, ObserverFormKeys) {
  const std::string observer =
      replace(kGood, "filter:\n", "filter:\n  form: observer\n  K: [[1], [2e-3]]\n  G_F: [[0.5], [1]]\n");
  const auto g = parse_gains_yaml(replace(observer, "{n: 2, m: 1, l: 1}", "{n: 2, m: 1, l: 1, r: 1}"), "g.yaml");
  EXPECT_TRUE(g.observer_form);
  EXPECT_EQ(g.K(1, 0), 2e-3);
  EXPECT_EQ(g.G_F.rows(), 2);
  EXPECT_EQ(g.G_F(0, 0), 0.5);
  EXPECT_FALSE(parse_gains_yaml(kGood, "g.yaml").observer_form);
  EXPECT_EQ(parse_gains_yaml(kGood, "g.yaml").G_F.cols(), 0);
  EXPECT_HAS(error_for(replace(observer, "  K: [[1], [2e-3]]\n", "")), "missing key 'filter.K'");
  EXPECT_HAS(error_for(replace(kGood, "filter:\n", "filter:\n  K: [[1], [2]]\n")),
             "filter.K: only an observer-form filter");
  EXPECT_HAS(error_for(replace(observer, "K: [[1], [2e-3]]", "K: [[1, 2], [3, 4]]")), "filter.K: expected 2x1");
  EXPECT_HAS(error_for(replace(observer, "G_F: [[0.5], [1]]", "G_F: [[0.5]]")), "filter.G_F: expected 2 rows");
  EXPECT_HAS(error_for(replace(observer, "form: observer", "form: observr")), "filter.form");
  EXPECT_HAS(error_for(replace(observer, "{n: 2, m: 1, l: 1}", "{n: 2, m: 1, l: 1, r: 2}")), "r");
}

// The filtered estimate (docs/maths.md (140)): filter.estimate, filter.M and filter.D_F
// (required for it and only for it), their shapes.
TEST(GainsFile, FilteredEstimateKeys) {
  const std::string filtered = replace(
      kGood, "filter:\n", "filter:\n  form: observer\n  estimate: filtered\n  K: [[1], [2e-3]]\n  M: [[0.9], [1e-3]]\n  D_F: [[0.5]]\n");
  const auto g = parse_gains_yaml(filtered, "g.yaml");
  EXPECT_TRUE(g.filtered);
  EXPECT_EQ(g.M(0, 0), 0.9);
  EXPECT_EQ(g.D_F(0, 0), 0.5);
  EXPECT_FALSE(parse_gains_yaml(kGood, "g.yaml").filtered);
  EXPECT_HAS(error_for(replace(filtered, "  M: [[0.9], [1e-3]]\n", "")), "missing key 'filter.M'");
  EXPECT_HAS(error_for(replace(filtered, "  D_F: [[0.5]]\n", "")), "missing key 'filter.D_F'");
  EXPECT_HAS(error_for(replace(filtered, "M: [[0.9], [1e-3]]", "M: [[0.9]]")), "filter.M: expected 2x1");
  EXPECT_HAS(error_for(replace(filtered, "D_F: [[0.5]]", "D_F: [[0.5, 1]]")), "filter.D_F: expected 1x1");
  EXPECT_HAS(error_for(replace(filtered, "form: observer", "form: augmented")),
             "filter.estimate: only an observer-form filter");
  EXPECT_HAS(error_for(replace(filtered, "estimate: filtered", "estimate: predicted")),
             "only a filtered estimate (filter.estimate: filtered) has");
  EXPECT_HAS(error_for(replace(filtered, "estimate: filtered", "estimate: filterd")), "filter.estimate");
}
