// The manoeuvring_target truth and stream (docs/maths.md §32.4–§32.5): check 001-U4 (frames),
// the ECI two-body truth against the relative two-body equations in the rotating frame
// (models/two_body.hpp, an independent integration), and the detector threshold against a
// χ² table.
#include <gtest/gtest.h>

#include <cmath>

#include "hinf/models/lvlh.hpp"
#include "hinf/models/two_body.hpp"
#include "hinf/sim/manoeuvring_run.hpp"
#include "hinf/sim/manoeuvring_truth.hpp"

namespace {

using namespace hinf::sim;
namespace m = hinf::models;

ManoeuvringScenario short_scenario(double duration) {
  ManoeuvringScenario s;
  s.duration = duration;
  s.noise = false;
  return s;
}

// 001-U4: with the chaser unforced LVLH1 = LVLH0 (T_m = I); the target's manoeuvre changes nothing there.
TEST(ManoeuvringTruth, UnforcedChaserFliesTheReferenceOrbitSoLvlh1IsLvlh0) {
  const ManoeuvringScenario s = short_scenario(1000);
  double worst = 0;
  for (const ManoeuvringTruthSample& x : manoeuvring_truth(s)) {
    const Eigen::Matrix3d Tm = m::lvlh_to_inertial(x.reference).transpose() * m::lvlh_to_inertial(x.chaser);
    worst = std::max(worst, (Tm - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(worst, 1e-12);
}

// 001-U4: with the chaser thrusting (case 6.2) and no noise, the measurement mapped LVLH1 → ECI →
// LVLH0 is the true relative position.
TEST(ManoeuvringTruth, MappedMeasurementIsTheTruePositionWhileTheChaserThrusts) {
  ManoeuvringScenario s = short_scenario(700);
  s.chaser_manoeuvres = s.target_manoeuvres;
  s.chaser_manoeuvres.front().accel = Eigen::Vector3d(0.3, -0.4, 0.2);  // also out of plane
  ManoeuvringRunOptions o;
  double worst = 0, rotated = 0;
  o.on_sample = [&](int, const ManoeuvringSample& x) {
    worst = std::max(worst, (x.measured_position - x.truth.head<3>()).norm());
  };
  run_manoeuvring(s, {ManoeuvreFilterSettings{}}, o, 1);
  EXPECT_LE(worst, 1e-6);
  // and LVLH1 has turned away from LVLH0 by then, so the check had something to undo
  const auto truth = manoeuvring_truth(s);
  const Eigen::Matrix3d Tm =
      m::lvlh_to_inertial(truth.back().reference).transpose() * m::lvlh_to_inertial(truth.back().chaser);
  rotated = (Tm - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  EXPECT_GT(rotated, 1e-3);
}

// 001-U4: both spacecraft in one plane: swapping the inclination and the node (the source's
// ambiguous Table 1) leaves the LVLH0 trajectory the same.
TEST(ManoeuvringTruth, SwappingInclinationAndNodeLeavesTheLvlh0TrajectoryUnchanged) {
  ManoeuvringScenario a = short_scenario(1000), b = a;
  for (m::OrbitalElements* el : {&b.target, &b.chaser}) std::swap(el->inclination, el->raan);
  const auto ta = manoeuvring_truth(a), tb = manoeuvring_truth(b);
  ASSERT_EQ(ta.size(), tb.size());
  double worst = 0;
  for (std::size_t k = 0; k < ta.size(); ++k)
    worst = std::max(worst, (ta[k].relative.head<3>() - tb[k].relative.head<3>()).norm());
  EXPECT_LE(worst, 1e-6);
  EXPECT_GT((ta[500].target.r - tb[500].target.r).norm(), 1e5);  // the inertial orbits do differ
}

// The ECI truth differenced into LVLH0 against the relative two-body equations integrated in the
// rotating frame of the (circular, unforced) chaser, with the target's thrust held in LVLH0.
TEST(ManoeuvringTruth, EciTruthMatchesTheRelativeTwoBodyEquationsInTheRotatingFrame) {
  ManoeuvringScenario s = short_scenario(800);
  s.target_manoeuvres.front().frame = ThrustFrame::Lvlh0;
  const auto truth = manoeuvring_truth(s);
  const m::RelativeTwoBody rel(s.mu, m::KeplerOrbit(truth.front().chaser, s.mu).mean_motion());
  Eigen::Matrix<double, 6, 1> X = truth.front().relative;
  double worst = 0;
  for (std::size_t k = 0; k + 1 < truth.size(); ++k) {
    const Eigen::Vector3d u = s.target_manoeuvres.front().on(truth[k].t) ? s.target_manoeuvres.front().accel
                                                                          : Eigen::Vector3d::Zero();
    X = rel.propagate(X, u, s.sample_time, 10);
    worst = std::max(worst, (X - truth[k + 1].relative).head<3>().norm());
    // the truth's interval-mean thrust in LVLH0 is the held one
    EXPECT_LE((truth[k].target_accel - u).norm(), 1e-12) << "t = " << truth[k].t;
  }
  EXPECT_LE(worst, 1e-3);  // metres, after 800 s and 100 km of separation
}

// χ²₃₀ at 1 − 10⁻³ is 59.703 (Abramowitz & Stegun, Table 26.8).
TEST(ManoeuvringRun, DetectorThresholdIsTheChiSquareQuantile) {
  EXPECT_NEAR(nis_window_threshold(10, 1e-3), 59.703, 1e-3);
  EXPECT_NEAR(nis_window_threshold(1, 0.05), 7.815, 1e-3);
}

}  // namespace
