// The simulation API (sim/family.hpp) called in-process — no subprocess, no files — gives the
// same run directory, byte for byte (timing apart), as the hinf-sim executable on the same scenario and
// options, for one scenario of every family; and the registry finds every family.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <unistd.h>

#include "api_test_support.hpp"
#include "hinf/common/error.hpp"
#include "hinf/sim/family.hpp"

namespace fs = std::filesystem;

namespace {

using hinf::test::slurp;
using hinf::test::timing_apart;

struct Case {
  const char* scenario;  // configs/scenarios/NAME.yaml
  const char* family;    // its family's name ("" for the Hill experiments)
  double duration;       // s
};

class SimulationApi : public ::testing::TestWithParam<Case> {};

TEST_P(SimulationApi, SameFilesAsTheExecutable) {
  const Case c = GetParam();
  const fs::path scenario = fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / (std::string(c.scenario) + ".yaml");
  hinf::sim::CampaignRequest request;
  request.scenario_path = scenario.string();
  request.scenario_text = slurp(scenario);
  request.runs = 2;
  request.seed = 7;
  request.jobs = 1;
  request.duration = c.duration;
  EXPECT_STREQ(hinf::sim::family_of(request.scenario_text, request.scenario_path).name(), c.family);
  const hinf::sim::CampaignResult result = hinf::sim::simulate(request);

  const fs::path out = fs::temp_directory_path() / ("simulation_api_" + std::string(c.scenario) + "_" +
                                                    std::to_string(::getpid()));
  fs::remove_all(out);
  std::ostringstream duration;
  duration << c.duration;
  const std::string cmd = std::string(HINF_SIM_EXE) + " " + scenario.string() + " -o " + out.string() +
                          " --runs 2 --seed 7 --jobs 1 --no-plots --quiet --duration " + duration.str() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  ASSERT_FALSE(result.files.empty());
  std::size_t files_on_disk = 0;
  for (const auto& entry : fs::directory_iterator(out))  // the data files, not plots or the manifest
    files_on_disk += entry.path().extension() != ".png" && entry.path().filename() != hinf::sim::kManifestName;
  EXPECT_EQ(files_on_disk, result.files.size());
  for (const auto& [name, bytes] : result.files)
    EXPECT_TRUE(timing_apart(slurp(out / name)) == timing_apart(bytes)) << c.scenario << ": " << name;
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(EveryFamily, SimulationApi,
                         ::testing::Values(Case{"paper-no-control", "", 300}, Case{"tumbling-hold-ideal", "tumbling_hold", 60},
                                           Case{"gps-ins-flyaround", "gps_ins_relative", 100},
                                           Case{"gyroless-attitude", "gyroless_attitude", 100},
                                           Case{"manoeuvring-target-chaser-free", "manoeuvring_target", 100}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.scenario;
                           for (char& ch : name) ch = ch == '-' ? '_' : ch;
                           return name;
                         });

TEST(SimulationApiRegistry, AnUnknownFamilyIsNamedWithTheKnownOnes) {
  try {
    hinf::sim::family_of("scenario: tumbling\n", "s.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("tumbling_hold"), std::string::npos) << e.what();
  }
  EXPECT_STREQ(hinf::sim::family_of("duration: 10\n", "s.yaml").name(), "");
}

}  // namespace
