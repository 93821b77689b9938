// A gps_ins_relative run (sim/gps_ins_run.hpp, docs/maths.md §29–§30): the EKF and the REKF on
// one measurement stream converge, stay consistent and never violate the γ condition.
#include <gtest/gtest.h>

#include <iostream>

#include "hinf/sim/gps_ins_run.hpp"

using namespace hinf::sim;

namespace {
std::vector<GpsInsFilterSettings> ekf_and_rekf() {
  GpsInsFilterSettings ekf, rekf;
  rekf.name = "rekf";
  rekf.kind = GpsInsFilterKind::Rekf;
  rekf.inertia_uncertainty_fraction = 0.3;
  return {ekf, rekf};
}
void print(const char* name, const GpsInsFilterStatistics& s) {
  std::cout << name << ": position max " << s.position_max.maxCoeff() << " m, velocity max " << s.velocity_max.maxCoeff()
            << " m/s, attitude max " << s.attitude_max.maxCoeff() << " deg, rate max " << s.rate_max.maxCoeff()
            << " deg/s, bias max " << s.bias_max.maxCoeff() << " deg/s, NEES " << s.nees_mean << ", gamma violations "
            << s.gamma_violations << ", failed " << s.failed_steps << "\n";
}
}  // namespace

TEST(GpsInsRun, EkfAndRekfConvergeOnOneStream) {
  GpsInsScenario s;
  s.duration = 3000;
  GpsInsRunOptions o;
  o.window_start = 2000;
  o.window_end = 3000;
  const auto stats = run_gps_ins(s, ekf_and_rekf(), o, 1);
  ASSERT_EQ(stats.size(), 2u);
  for (const auto& st : stats) {
    print("filter", st);
    EXPECT_FALSE(st.diverged);
    EXPECT_EQ(st.gamma_violations, 0);
    EXPECT_EQ(st.failed_steps, 0);
    EXPECT_LE(st.position_max.maxCoeff(), 0.15);
    EXPECT_LE(st.velocity_max.maxCoeff(), 3e-4);
  }
  // the EKF, told the true noise (p = 0): the accuracy and a NEES near 15 on this
  // run (one run, 1000 samples: not the 20-run χ² test)
  EXPECT_LE(stats[0].attitude_max.maxCoeff(), 3e-3);
  EXPECT_LE(stats[0].rate_max.maxCoeff(), 2e-5);
  EXPECT_GT(stats[0].nees_mean, 10.0);
  EXPECT_LT(stats[0].nees_mean, 22.0);
  // the REKF assumes 30 % products of inertia (p_f = 0.3): its Q on ω is ~1e5 times the true
  // one at p = 0, so it leans on the gyro and its attitude is ~10× the EKF's (measured 0.0103°)
  EXPECT_LE(stats[1].attitude_max.maxCoeff(), 0.03);
  EXPECT_LT(stats[1].nees_mean, stats[0].nees_mean);
}
