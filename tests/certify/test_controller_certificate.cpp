// The controller's certificate (certify/controller_certificate.hpp) and the PBH test
// (certify/pbh.hpp) on loops whose answers are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hinf/certify/controller_certificate.hpp"
#include "hinf/certify/pbh.hpp"
#include "hinf/common/error.hpp"

namespace {

using Eigen::MatrixXd;

MatrixXd one_by_one(double v) { return MatrixXd::Constant(1, 1, v); }

// ẋ = a x + w + u, z = x, y = x: one state, every channel scalar.
hinf::GeneralisedPlant scalar_loop_plant(double a, hinf::TimeDomain time) {
  hinf::GeneralisedPlant P;
  P.time = time;
  P.sample_time = time == hinf::TimeDomain::Discrete ? 0.1 : 0;
  P.A = one_by_one(a);
  P.B1 = one_by_one(1);
  P.B2 = one_by_one(1);
  P.C1 = one_by_one(1);
  P.C2 = one_by_one(1);
  P.D11 = one_by_one(0);
  P.D12 = one_by_one(0);
  P.D21 = one_by_one(0);
  return P;
}

// u = d y through the feedthrough; the controller's own state (pole p) is not coupled.
hinf::Controller feedthrough_controller(double d, double p) {
  return {one_by_one(p), one_by_one(0), one_by_one(0), one_by_one(d)};
}

}  // namespace

// ẋ = x + w + u with u = −3 y: ẋ = −2 x + w, T_zw = 1/(s + 2), ‖T_zw‖∞ = 1/2 at ω = 0;
// poles −2 and the controller's −1.
TEST(ControllerCertificate, ContinuousLoopNormAndPolesAreTheClosedForm) {
  const auto P = scalar_loop_plant(1, hinf::TimeDomain::Continuous);
  const auto c = hinf::certify::certify_controller(P, feedthrough_controller(-3, -1), 0.5, {});
  EXPECT_TRUE(c.stable);
  EXPECT_NEAR(c.stability_margin_value, -1, 1e-12);
  EXPECT_NEAR(c.max_pole_modulus, 2, 1e-12);
  EXPECT_NEAR(c.closed_loop_hinf_norm, 0.5, 0.5 * 1e-9);
  EXPECT_GE(c.closed_loop_hinf_norm, 0.5 * (1 - 1e-12));  // an upper value
  EXPECT_NEAR(c.peak_frequency, 0, 1e-6);
  EXPECT_TRUE(c.passed);
  EXPECT_FALSE(hinf::certify::certify_controller(P, feedthrough_controller(-3, -1), 0.49, {}).passed);
}

// x⁺ = x/2 + w + u with u = −y/4: x⁺ = x/4 + w, T_zw = 1/(z − 1/4), ‖T_zw‖∞ = 4/3 at z = 1;
// spectral radius 1/2 (the controller's pole).
TEST(ControllerCertificate, DiscreteLoopNormAndSpectralRadiusAreTheClosedForm) {
  const auto P = scalar_loop_plant(0.5, hinf::TimeDomain::Discrete);
  const auto c = hinf::certify::certify_controller(P, feedthrough_controller(-0.25, 0.5), 4.0 / 3, {});
  EXPECT_TRUE(c.stable);
  EXPECT_NEAR(c.stability_margin_value, 0.5, 1e-12);
  EXPECT_NEAR(c.closed_loop_hinf_norm, 4.0 / 3, 4.0 / 3 * 1e-9);
  EXPECT_TRUE(c.passed);
}

TEST(ControllerCertificate, UnstableLoopFailsWithInfiniteNorm) {
  const auto P = scalar_loop_plant(1, hinf::TimeDomain::Continuous);
  const auto c = hinf::certify::certify_controller(P, feedthrough_controller(-0.5, -1), 1e6, {});  // ẋ = x/2 + w
  EXPECT_FALSE(c.stable);
  EXPECT_NEAR(c.stability_margin_value, 0.5, 1e-12);
  EXPECT_TRUE(std::isinf(c.closed_loop_hinf_norm));
  EXPECT_FALSE(c.passed);
}

// ΔA = h F e on ẋ = −2 x + w: T_qp = e h/(s + 2), ‖T_qp‖∞ = |e h|/2; robust iff < 1.
TEST(ControllerCertificate, SmallGainAndPoleDiskAreChecked) {
  const auto P = scalar_loop_plant(1, hinf::TimeDomain::Continuous);
  const auto K = feedthrough_controller(-3, -1);
  hinf::certify::ControllerChecks checks;
  checks.robust = hinf::UncertaintyChannel{one_by_one(1.5), one_by_one(1)};
  auto c = hinf::certify::certify_controller(P, K, 0.5, checks);
  EXPECT_NEAR(*c.robust_channel_norm, 0.75, 1e-9);
  EXPECT_TRUE(c.robustly_stable);
  EXPECT_TRUE(c.passed);
  checks.robust = hinf::UncertaintyChannel{one_by_one(2.5), one_by_one(1)};
  c = hinf::certify::certify_controller(P, K, 0.5, checks);
  EXPECT_NEAR(*c.robust_channel_norm, 1.25, 1e-9);
  EXPECT_FALSE(c.robustly_stable);
  EXPECT_FALSE(c.passed);
  checks.robust.reset();
  checks.pole_disk_radius = 1.5;  // the pole −2 is outside
  c = hinf::certify::certify_controller(P, K, 0.5, checks);
  EXPECT_FALSE(c.poles_in_disk);
  EXPECT_FALSE(c.passed);
}

// A controller of other dimensions than the plant's is refused, naming the matrix; no
// read past an array (the sanitizer build runs this test).
TEST(ControllerCertificate, ControllerThatDoesNotFitThePlantIsInvalidInput) {
  const auto P = scalar_loop_plant(1, hinf::TimeDomain::Continuous);
  hinf::Controller K = feedthrough_controller(-3, -1);
  K.B_K = MatrixXd::Zero(1, 2);  // as if for two measurements
  try {
    hinf::certify::certify_controller(P, K, 1, {});
    FAIL() << "no error";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_EQ(e.key(), "B_K");
    EXPECT_NE(std::string(e.what()).find("controller.B_K: expected 1x1 for this plant (ny = 1 measurements, nu = 1 controls), got 1x2"), std::string::npos) << e.what();
  }
  K = feedthrough_controller(-3, -1);
  K.A_K = MatrixXd::Zero(2, 2);  // two states, B_K and C_K for one
  EXPECT_THROW(hinf::certify::certify_controller(P, K, 1, {}), hinf::Error);
}

// A = diag(2, 1/2) (discrete): the mode 2 along e₁ is unseen by X = [0 1], seen by [1 0];
// the stable mode 1/2 is never reported.
TEST(Pbh, DiscreteUnseenModeAndItsDirection) {
  MatrixXd A = MatrixXd::Zero(2, 2);
  A.diagonal() << 2, 0.5;
  const MatrixXd x_second = (MatrixXd(1, 2) << 0, 1).finished();
  const auto m = hinf::certify::unseen_unstable_mode(A, x_second, /*discrete=*/true);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(std::abs(m->lambda - 2.0), 0, 1e-12);
  EXPECT_NEAR(std::abs(m->direction(0)), 1, 1e-12);
  EXPECT_NEAR(std::abs(m->direction(1)), 0, 1e-12);
  EXPECT_FALSE(hinf::certify::unseen_unstable_mode(A, (MatrixXd(1, 2) << 1, 0).finished(), true).has_value());
}

// In continuous time the region is Re λ ≥ 0: λ = 0.5 counts, λ = −3 does not.
TEST(Pbh, ContinuousRegionIsTheClosedRightHalfPlane) {
  MatrixXd A = MatrixXd::Zero(2, 2);
  A.diagonal() << -3, 0.5;
  const auto m = hinf::certify::unseen_unstable_mode(A, (MatrixXd(1, 2) << 1, 0).finished(), /*discrete=*/false);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(std::abs(m->lambda - 0.5), 0, 1e-12);
  EXPECT_FALSE(hinf::certify::unseen_unstable_mode(A, (MatrixXd(1, 2) << 0, 1).finished(), false).has_value());
}
