// The jobs' JSON (synth/src/job_json.hpp): a file the tool writes, converted from its YAML,
// gives back every number bit for bit and every string as a string; numbers that YAML cannot
// hold in JSON (non-finite) become null.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "job_json.hpp"  // private to synth (hinf_synth_private)

namespace hinf::synth {
namespace {

// Bitwise equality of two doubles (-0 and 0 differ; no NaN is compared here).
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(JobJson, ScalarsKeepTheirTypeAndNumbersTheirBits) {
  const Json j = job_json::from_yaml(
      "a: 0.47170382496129287\n"
      "b: -5.5156618202045068e-05\n"
      "c: 1e+20\n"
      "d: 139\n"
      "e: true\n"
      "f: false\n"
      "g: \"solved: relative gap below tolerance\"\n"
      "h: log-det barrier path following\n"
      "i: \"123\"\n"
      "j: .nan\n"
      "k: -.inf\n"
      "l: ~\n"
      "m: 1548f3a9588eef048b8faddd821b88c85cc6dd4d1775cd62ef717be18513daa8\n"
      "n: 3.11.9\n"
      "o: 4.9406564584124654e-324\n"
      "p: -0\n");
  EXPECT_TRUE(same_bits(j["a"].get<double>(), 0.47170382496129287));
  EXPECT_TRUE(same_bits(j["b"].get<double>(), -5.5156618202045068e-05));
  EXPECT_TRUE(same_bits(j["c"].get<double>(), 1e20));
  EXPECT_TRUE(j["d"].is_number_integer());
  EXPECT_EQ(j["d"].get<int>(), 139);
  EXPECT_EQ(j["e"], true);
  EXPECT_EQ(j["f"], false);
  EXPECT_EQ(j["g"], "solved: relative gap below tolerance");
  EXPECT_EQ(j["h"], "log-det barrier path following");
  EXPECT_EQ(j["i"], "123");  // quoted: a string, though it reads as a number
  EXPECT_TRUE(j["j"].is_null());
  EXPECT_TRUE(j["k"].is_null());
  EXPECT_TRUE(j["l"].is_null());
  EXPECT_EQ(j["m"], "1548f3a9588eef048b8faddd821b88c85cc6dd4d1775cd62ef717be18513daa8");
  EXPECT_EQ(j["n"], "3.11.9");  // a version, not a number
  EXPECT_TRUE(same_bits(j["o"].get<double>(), std::numeric_limits<double>::denorm_min()));
  EXPECT_EQ(j["p"].get<int>(), 0);
}

TEST(JobJson, MapsKeepTheFilesOrderAndMatricesTheirShape) {
  const Json j = job_json::from_yaml("z: 1\na:\n  - [1.5, -2.25]\n  - [3, 4e-300]\nm: {n: 6, m: 3}\n");
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j.begin().key(), "z");  // the file's order, not sorted
  ASSERT_EQ(j["a"].size(), 2u);
  ASSERT_EQ(j["a"][1].size(), 2u);
  EXPECT_TRUE(same_bits(j["a"][1][1].get<double>(), 4e-300));
  EXPECT_EQ(j["m"]["n"], 6);
}

TEST(JobJson, NumbersDumpedAndParsedAgainKeepTheirBits) {
  // nlohmann writes the shortest digits that read back: the JSON text round-trips.
  for (const double v : {0.1, 1.0 / 3.0, 2.2250738585072014e-308, 1.7976931348623157e308, -9.8813129168249309e-324,
                         0.35872371288998356}) {
    Json j;
    j["v"] = v;
    EXPECT_TRUE(same_bits(Json::parse(json_line(j))["v"].get<double>(), v)) << json_line(j);
  }
}

TEST(JobJson, SolvedCarriesTheSchemaGammaAndTheFile) {
  const std::string line = job_json::solved("solve", "filter", "cfg.yaml", 0.35872371288998356, "gains",
                                            "format: hinf-gains/1\ngamma: 0.35872371288998356\n");
  const Json j = Json::parse(line);
  EXPECT_EQ(j["schema"], "hinf-synth.solve/1");
  EXPECT_EQ(j["kind"], "filter");
  EXPECT_EQ(j["config"], "cfg.yaml");
  EXPECT_TRUE(same_bits(j["gamma"].get<double>(), 0.35872371288998356));
  EXPECT_EQ(j["file"]["format"], "hinf-gains/1");
  EXPECT_EQ(line.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace hinf::synth
