// Strict scenario parsing: unknown keys and bad values are errors naming the key.
#include <gtest/gtest.h>

#include <string>

#include "hinf/sim/scenario_yaml.hpp"

namespace {

using hinf::sim::parse_scenario;
using hinf::Error;
using hinf::ErrorCode;

const std::string kMinimal = R"(
duration: 10
truth: {initial_state: [600, 550, 1040, 0.02, -0.08, 0.03]}
filters: {ekf: {}}
)";

std::string error_of(const std::string& text) {
  try {
    parse_scenario(text, "/tmp/s.yaml");
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    return e.what();
  }
  return "";
}

TEST(ScenarioYaml, MinimalHasSpecDefaults) {
  const auto s = parse_scenario(kMinimal, "/tmp/s.yaml");
  EXPECT_DOUBLE_EQ(s.sample_time, 0.1);
  EXPECT_EQ(s.steps(), 101);
  EXPECT_DOUBLE_EQ(s.orbital_rate, 7.2722e-5);
  EXPECT_DOUBLE_EQ(s.initial_estimate(2), 1000.0);  // initial estimate of docs/maths.md §9.8
  EXPECT_DOUBLE_EQ(s.metric_settings().steady_state_start_s, 5.0);
  EXPECT_TRUE(s.filters.ekf);
  EXPECT_FALSE(s.filters.rekf.has_value());
}

TEST(ScenarioYaml, UnknownKeyNamesPathAndSuggests) {
  const std::string e = error_of(kMinimal + "metrics: {converge_treshold: 1}\n");
  EXPECT_NE(e.find("metrics.converge_treshold"), std::string::npos) << e;
  EXPECT_NE(e.find("/tmp/s.yaml:5:11: unknown key 'metrics.converge_treshold' (did you mean 'converge_threshold'?)"),
            std::string::npos) << e;
  const std::string e2 = error_of(kMinimal + "durations: 5\n");
  EXPECT_NE(e2.find("durations"), std::string::npos) << e2;
}

TEST(ScenarioYaml, BadValuesNameTheKey) {
  EXPECT_NE(error_of("duration: 10.05\ntruth: {initial_state: [1,2,3,4,5,6]}\nfilters: {ekf: {}}\n").find("duration"),
            std::string::npos);
  EXPECT_NE(error_of("duration: 10\ntruth: {initial_state: [1,2,3]}\nfilters: {ekf: {}}\n").find("truth.initial_state"),
            std::string::npos);
  EXPECT_NE(error_of(kMinimal + "process_noise: {type: student_t, sigma: 1, dof: 2}\n").find("process_noise.dof"),
            std::string::npos);
  EXPECT_NE(error_of(kMinimal + "process_noise: [{type: gaussian, sigma: 1}, {type: gausian, sigma: 1}]\n")
                .find("process_noise[1].type"),
            std::string::npos);
  EXPECT_NE(error_of(kMinimal + "measurement: {C_bl: [[1,0,0],[0,1,0],[0,0,2]]}\n").find("measurement.C_bl"),
            std::string::npos);
  EXPECT_NE(error_of(kMinimal + "control: {law: state_feedback}\n").find("control.K"), std::string::npos);
  EXPECT_NE(error_of("duration: 10\ntruth: {delta: -1, initial_state: [1,2,3,4,5,6]}\nfilters: {ekf: {}}\n")
                .find("truth.delta"),
            std::string::npos);
  EXPECT_NE(error_of("duration: 10\ntruth: {initial_state: [1,2,3,4,5,6]}\nfilters: {hinf: {gains: nope.yaml}}\n")
                .find("filters.hinf.gains"),
            std::string::npos);
  EXPECT_NE(error_of("duration: 10\ntruth: {initial_state: [1,2,3,4,5,6]}\nfilters: {}\n").find("filters"),
            std::string::npos);
  EXPECT_NE(error_of("duration: [\n").find("YAML syntax error"), std::string::npos);
}

TEST(ScenarioYaml, ConvergeWindow) {
  EXPECT_DOUBLE_EQ(parse_scenario(kMinimal, "/tmp/s.yaml").metric_settings().converge_window_s, 0.0);
  EXPECT_DOUBLE_EQ(parse_scenario(kMinimal + "metrics: {converge_window: 2.5}\n", "/tmp/s.yaml")
                       .metric_settings()
                       .converge_window_s,
                   2.5);
  EXPECT_NE(error_of(kMinimal + "metrics: {converge_window: -1}\n").find("metrics.converge_window"),
            std::string::npos);
  const std::string e = error_of(kMinimal + "metrics: {converge_window: 11}\n");
  EXPECT_NE(e.find("metrics.converge_window"), std::string::npos) << e;
  EXPECT_NE(e.find("longer than the duration"), std::string::npos) << e;
}

TEST(ScenarioYaml, NoiseListsAndControl) {
  const auto s = parse_scenario(kMinimal + R"(
control: {law: state_feedback, on: truth, K: [[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,0,0,0]]}
measurement:
  range: [{type: gaussian, sigma: 0.1}, {type: impulsive, probability: 0.01, magnitude: 2}]
  azimuth: {type: laplace, sigma: 1e-4}
)",
                                    "/tmp/s.yaml");
  EXPECT_EQ(s.range_noise.size(), 2u);
  EXPECT_EQ(s.azimuth_noise.size(), 1u);
  EXPECT_EQ(s.control_law, hinf::sim::ControlLaw::StateFeedback);
  EXPECT_DOUBLE_EQ(s.K(1, 1), 1.0);
}

}  // namespace
