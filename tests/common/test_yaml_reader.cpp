// The one strict YAML reader (hinf::YamlReader, common/) behind configs, gains files and
// scenarios: a quoted number, a duplicate key and an unknown key are refused the same way
// by each format's real reader (hinf::synth::parse_config,
// hinf::runtime_yaml::parse_gains_yaml, hinf::sim::parse_scenario): ErrorCode::InvalidInput,
// a message starting "name.yaml:LINE:COL: " at the offending node, the full key path, and
// for an unknown key the did-you-mean of hinf::closest_match.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "hinf/common/error.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/sim/scenario_yaml.hpp"
#include "hinf/synth/config.hpp"

namespace {

using hinf::Error;
using hinf::ErrorCode;

// One file format: its real reader and a valid file in it.
struct Format {
  const char* file;  // the source name the messages carry
  std::function<void(const std::string& text, const std::string& name)> read;
  std::string valid;
};

const Format kConfig{"config.yaml",
                     [](const std::string& t, const std::string& n) { hinf::synth::parse_config(t, n); },
                     "system:\n"                      // 1
                     "  A: [[0.5, 0.1], [0, 0.4]]\n"  // 2
                     "  B: [[1], [0]]\n"              // 3
                     "  C: [[1, 0]]\n"                // 4
                     "  D: [[0.1]]\n"                 // 5
                     "  L: [[1, 0]]\n"                // 6
                     "solver:\n"                      // 7
                     "  lmi_margin: 1e-9\n"};         // 8

const Format kGains{"gains.yaml",
                    [](const std::string& t, const std::string& n) { hinf::runtime_yaml::parse_gains_yaml(t, n); },
                    "format: hinf-gains/1\n"          // 1
                    "gamma: 1.5\n"                    // 2
                    "dimensions: {n: 1, m: 1, l: 1}\n"  // 3
                    "filter:\n"                       // 4
                    "  A_F: [[0.5]]\n"                // 5
                    "  B_F: [[1]]\n"                  // 6
                    "  C_F: [[2]]\n"};                // 7

const Format kScenario{"scenario.yaml",
                       [](const std::string& t, const std::string& n) { hinf::sim::parse_scenario(t, n); },
                       "duration: 10\n"                                                  // 1
                       "truth: {delta: 0.1, initial_state: [600, 550, 1040, 0, 0, 0]}\n"  // 2
                       "filters: {ekf: {}}\n"                                            // 3
                       "metrics: {converge_threshold: 1}\n"};                            // 4

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Expects `text` to be refused with Error(InvalidInput) whose message starts with
// "<file>:<line>:<col>: " and contains `rest`.
void expect_refused(const Format& format, const std::string& text, int line, int col,
                    const std::string& rest) {
  const std::string where = std::string(format.file) + ":" + std::to_string(line) + ":" +
                            std::to_string(col) + ": ";
  try {
    format.read(text, format.file);
    ADD_FAILURE() << format.file << " accepted:\n" << text;
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << message;
    EXPECT_EQ(hinf::exit_code(e.code()), 2);
    EXPECT_EQ(message.rfind(where, 0), 0u) << message << "\ndoes not start with " << where;
    EXPECT_NE(message.find(rest), std::string::npos) << message << "\nlacks " << rest;
  } catch (const std::exception& e) {
    ADD_FAILURE() << format.file << ": not a hinf::Error: " << e.what();
  }
}

TEST(OneStrictReader, ValidFilesAreRead) {
  for (const Format* f : {&kConfig, &kGains, &kScenario})
    EXPECT_NO_THROW(f->read(f->valid, f->file)) << f->file;
}

TEST(OneStrictReader, QuotedNumberIsRefusedIdentically) {
  const std::string quoted = ": expected a number, got the quoted string \"0.1\" (write numbers without quotes)";
  expect_refused(kConfig, replaced(kConfig.valid, "[[0.5, 0.1]", "[[0.5, \"0.1\"]"), 2, 13,
                 "system.A entry (1, 2)" + quoted);
  expect_refused(kGains, replaced(kGains.valid, "A_F: [[0.5]]", "A_F: [[\"0.1\"]]"), 5, 10,
                 "filter.A_F entry (1, 1)" + quoted);
  expect_refused(kGains, replaced(kGains.valid, "gamma: 1.5", "gamma: \"0.1\""), 2, 8, "gamma" + quoted);
  expect_refused(kScenario, replaced(kScenario.valid, "delta: 0.1", "delta: \"0.1\""), 2, 16,
                 "truth.delta" + quoted);
  // an integer too
  expect_refused(kGains, replaced(kGains.valid, "n: 1,", "n: \"1\","), 3, 17,
                 "dimensions.n: expected an integer, got the quoted string \"1\"");
}

TEST(OneStrictReader, DuplicateKeyIsRefusedIdentically) {
  expect_refused(kConfig, kConfig.valid + "  lmi_margin: 1e-8\n", 9, 3, "duplicate key 'solver.lmi_margin'");
  expect_refused(kGains, kGains.valid + "  B_F: [[3]]\n", 8, 3, "duplicate key 'filter.B_F'");
  expect_refused(kScenario, replaced(kScenario.valid, "{delta: 0.1,", "{delta: 0.1, delta: 0.2,"), 2, 21,
                 "duplicate key 'truth.delta'");
}

TEST(OneStrictReader, UnknownKeyIsRefusedIdenticallyWithASuggestion) {
  expect_refused(kConfig, replaced(kConfig.valid, "lmi_margin", "lmi_margn"), 8, 3,
                 "unknown key 'solver.lmi_margn' (did you mean 'lmi_margin'?)");
  expect_refused(kGains, replaced(kGains.valid, "  C_F:", "  C_FF:"), 7, 3,
                 "unknown key 'filter.C_FF' (did you mean 'C_F'?)");
  expect_refused(kScenario, replaced(kScenario.valid, "converge_threshold", "converge_treshold"), 4, 11,
                 "unknown key 'metrics.converge_treshold' (did you mean 'converge_threshold'?)");
}

TEST(OneStrictReader, ExtraDocumentsAreRefusedIdentically) {
  // the location is the second document's first node
  expect_refused(kConfig, kConfig.valid + "---\n" + kConfig.valid, 10, 1, "2 YAML documents");
  expect_refused(kGains, kGains.valid + "---\n" + kGains.valid, 9, 1, "2 YAML documents");
  expect_refused(kScenario, kScenario.valid + "---\n" + kScenario.valid, 6, 1, "2 YAML documents");
}

// A few kilobytes must not ask for gigabytes: declared sizes are capped before any
// matrix is allocated ({diag: [...]} of n entries is n×n; YAML aliases repeat rows).
TEST(OneStrictReader, OversizedMatricesAreRefusedBeforeAllocation) {
  std::string many = "0.5";
  for (int i = 1; i < 30000; ++i) many += ", 0.5";
  expect_refused(kConfig, replaced(kConfig.valid, "A: [[0.5, 0.1], [0, 0.4]]", "A: {diag: [" + many + "]}"), 2, 13,
                 "system.A.diag: 30000 entries; a vector or matrix read from a file has at most 1000");
  std::string rows = "[&r [" + many + "]";
  for (int i = 1; i < 3; ++i) rows += ", *r";
  expect_refused(kGains, replaced(kGains.valid, "A_F: [[0.5]]", "A_F: " + rows + "]"), 5, 9,
                 "filter.A_F row 1: 30000 entries; a vector or matrix read from a file has at most 1000");
  std::string aliased = "[&r [0.5]";
  for (int i = 1; i < 1001; ++i) aliased += ", *r";
  expect_refused(kGains, replaced(kGains.valid, "A_F: [[0.5]]", "A_F: " + aliased + "]"), 5, 8,
                 "filter.A_F: 1001 rows; a vector or matrix read from a file has at most 1000");
}

// yaml-cpp 0.7's LoadAll never ends on a stray ',' outside [ ] or { } (it yields empty
// documents without consuming it, allocating until memory runs out; found by
// fuzz/fuzz_gains): refused at once, at the ','.
TEST(OneStrictReader, StrayFlowIndicatorIsRefusedNotLoopedOn) {
  const std::string stall = "YAML syntax error: the parser cannot read past this point";
  expect_refused(kConfig, ",\n", 1, 1, stall);
  expect_refused(kGains, "[1, 2]\n,\n", 2, 1, stall);
  expect_refused(kScenario, ",,,, 1D\n", 1, 1, stall);
  // after a block map yaml-cpp itself reports it
  expect_refused(kConfig, kConfig.valid + ",\n", 9, 1, "YAML syntax error: end of map not found");
}

// yaml-cpp's parser recurses: nesting is refused at its depth guard, by name.
TEST(OneStrictReader, DeepNestingIsRefusedByName) {
  const std::string deep = std::string(5000, '[') + std::string(5000, ']');
  // the guard fires at depth 500; yaml-cpp marks the end of the flow
  expect_refused(kConfig, replaced(kConfig.valid, "[[0.5, 0.1], [0, 0.4]]", deep), 2, 10006,
                 "lists or maps nested 500 levels deep");
  expect_refused(kGains, replaced(kGains.valid, "[[0.5]]", deep), 5, 10008, "lists or maps nested 500 levels deep");
  expect_refused(kScenario, replaced(kScenario.valid, "[600, 550, 1040, 0, 0, 0]", deep), 2, 10036,
                 "lists or maps nested 500 levels deep");
}

// ---- the reader's own vocabulary (what the three formats share) --------------------

hinf::YamlMap map_of(const hinf::YamlReader& reader, const YAML::Node& node,
                     const std::vector<std::string>& keys,
                     hinf::EmptyMap empty = hinf::EmptyMap::Refused) {
  return reader.map(node, "m", keys, empty);
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(YamlReader, OptionalKeysFallBackAndRequiredKeysAreNamed) {
  const hinf::YamlReader reader("r.yaml");
  const YAML::Node root = reader.load("m: {a: 2, w: zoh}\n", "empty");
  const hinf::YamlMap m = map_of(reader, root["m"], {"a", "b", "w"});
  EXPECT_EQ(m.positive("a"), 2.0);
  EXPECT_EQ(m.number("b", 7.0), 7.0);
  EXPECT_EQ(m.choice("w", {"euler", "zoh"}), "zoh");
  EXPECT_EQ(message_of([&] { m.number("b"); }), "r.yaml:1:4: missing key 'm.b'");
  EXPECT_EQ(message_of([&] { m.fail_value("a", m.integer("a"), "must be odd"); }),
            "r.yaml:1:8: m.a = 2: must be odd");
}

TEST(YamlReader, StringEnumsSuggest) {
  const hinf::YamlReader reader("r.yaml");
  const YAML::Node root = reader.load("w: eular\n", "empty");
  EXPECT_EQ(message_of([&] { reader.choice(root["w"], "w", {"euler", "zoh"}); }),
            "r.yaml:1:4: w = 'eular': must be 'euler' or 'zoh' (did you mean 'euler'?)");
}

TEST(YamlReader, EmptyMapsOnlyWhereAllowed) {
  const hinf::YamlReader reader("r.yaml");
  const YAML::Node root = reader.load("e: {}\nn:\n", "empty");
  EXPECT_NO_THROW(map_of(reader, root["e"], {}, hinf::EmptyMap::Allowed));
  EXPECT_NO_THROW(map_of(reader, root["n"], {}, hinf::EmptyMap::Allowed));
  EXPECT_NE(message_of([&] { map_of(reader, root["e"], {"a"}); }).find("'m' is an empty map"),
            std::string::npos);
  const YAML::Node extra = reader.load("e: {x: 1}\n", "empty");
  EXPECT_NE(message_of([&] { map_of(reader, extra["e"], {}, hinf::EmptyMap::Allowed); })
                .find("unknown key 'm.x' (no keys are allowed here)"),
            std::string::npos);
}

TEST(YamlReader, ListsVectorsAndShapedMatrices) {
  const hinf::YamlReader reader("r.yaml");
  const YAML::Node root = reader.load("v: [1, 2, 3]\nM: {diag: [1, 2]}\nL: [{a: 1}, {a: 2}]\n", "empty");
  EXPECT_EQ(reader.vector(root["v"], "v", 3)(2), 3.0);
  EXPECT_EQ(message_of([&] { reader.vector(root["v"], "v", 6); }),
            "r.yaml:1:4: v: expected a list of 6 numbers, got 3");
  EXPECT_EQ(reader.matrix(root["M"], "M", 2, 2)(1, 1), 2.0);
  EXPECT_NE(message_of([&] { reader.matrix(root["M"], "M", 3, 6); }).find("M: expected a 3x6 matrix, got 2x2"),
            std::string::npos);
  EXPECT_NE(message_of([&] { reader.matrix(root["M"], "M", hinf::MatrixForms::RowsOnly); })
                .find("M: expected a matrix as nested rows"),
            std::string::npos);
  const auto items = reader.one_or_list(root["L"], "L");
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[1].second, "L[1]");
  EXPECT_EQ(reader.one_or_list(root["L"][0], "L").front().second, "L");
}

TEST(YamlReader, OneDocument) {
  const hinf::YamlReader reader("r.yaml");
  EXPECT_EQ(message_of([&] { reader.load("# nothing\n", "empty file"); }), "r.yaml: empty file");
  EXPECT_NE(message_of([&] { reader.load("a: 1\n---\nb: 2\n", "empty"); }).find("2 YAML documents"),
            std::string::npos);
  EXPECT_EQ(message_of([&] { reader.load("a: [1\n", "empty"); }).rfind("r.yaml:", 0), 0u);
}

}  // namespace
