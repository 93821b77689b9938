// Obtaining a scenario's filter gains (sim/gains_source.hpp): the library never prints; a
// synthesis is announced through the caller's status log, a gains file is read silently,
// and the gains obtained either way are the same filter.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hinf/sim/gains_source.hpp"

TEST(GainsSource, SynthesisIsAnnouncedThroughTheStatusLogOnly) {
  hinf::sim::LtiGainsSource from_config;
  from_config.synthesize_path = std::string(HINF_SOURCE_DIR) + "/configs/paper-dbar0.05.yaml";
  std::vector<std::string> lines;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const hinf::sim::ObtainedGains synthesised =
      hinf::sim::obtain_gains(from_config, [&lines](const std::string& line) { lines.push_back(line); });
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "synthesising from " + from_config.synthesize_path + " ...");
  ASSERT_TRUE(synthesised.gamma.has_value());

  hinf::sim::LtiGainsSource from_file;
  from_file.gains_path = std::string(HINF_SOURCE_DIR) + "/tests/golden/paper-dbar0.05.yaml";
  lines.clear();
  const hinf::sim::ObtainedGains read =
      hinf::sim::obtain_gains(from_file, [&lines](const std::string& line) { lines.push_back(line); });
  EXPECT_TRUE(lines.empty());
  EXPECT_NEAR(*read.gamma, *synthesised.gamma, 1e-6 * *read.gamma);  // the golden's rtol
  // no log at all is allowed too
  EXPECT_NO_THROW(hinf::sim::obtain_gains(from_file, nullptr));
}
