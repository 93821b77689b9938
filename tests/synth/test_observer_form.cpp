// The observer-form filter (docs/maths.md §18): detectable plants (integrators), known
// inputs, the LMI (124) against the closed form (127) for scalar plants and against the
// Riccati predictor of §8.1 (an independent computation of the same optimum), the
// pre-flight's undetectable mode (126), invariance under state coordinates, and the runtime
// flying the known input.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <random>
#include <string>

#include "hinf/certify/error_system.hpp"
#include "hinf/certify/h2_norm.hpp"
#include "hinf/certify/riccati_filter.hpp"
#include "hinf/common/error.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/hill_plant.hpp"
#include "hinf/synth/synthesis.hpp"
#include "example_plants.hpp"
#include "random_plants.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using hinf::FilterForm;
using hinf::Plant;
using hinf::synth::FormChoice;
using hinf::synth::Settings;

using hinf::test::certain_plant;
using hinf::test::double_integrator;
using hinf::test::triple_integrator_with_input;

using hinf::test::scalar_plant;

// docs/maths.md (127): γ(κ) for the gain κ = k c of a scalar plant.
double scalar_gamma(double a, double b, double c, double d, double l, double kappa) {
  const double rho2 = (d / c) * (d / c);
  return std::abs(l) * std::sqrt(b * b + kappa * kappa * rho2) / (1 - std::abs(a - kappa));
}

// The closed-form optimum of (127): the branch minimisers κ₁, κ₂ or the dead-beat κ = a.
double scalar_optimum(double a, double b, double c, double d, double l) {
  const double rho2 = (d / c) * (d / c);
  if (a < 1) {
    const double k1 = b * b / (rho2 * (1 - a));
    if (k1 <= a) return scalar_gamma(a, b, c, d, l, k1);
  }
  if (a > -1) {
    const double k2 = -b * b / (rho2 * (1 + a));
    if (k2 >= a) return scalar_gamma(a, b, c, d, l, k2);
  }
  return scalar_gamma(a, b, c, d, l, a);
}

Settings observer_settings() {
  Settings s;
  s.form = FormChoice::Observer;
  return s;
}

TEST(ObserverForm, ScalarClosedFormIsItsOwnMinimum) {
  // (127) minimised by a dense scan, independently of the branch analysis
  const double cases[][5] = {{1, 1, 1, 1, 1},     {1.2, 0.3, 2, 0.5, 1}, {0.5, 1, 1, 0.2, 2},
                             {-0.7, 1, 1, 1, 1},  {0.3, 0.1, -1, 1, 1},  {-1.5, 1, 1, 0.1, 1}};
  for (const auto& k : cases) {
    double best = INFINITY;
    for (int i = 1; i < 2000000; ++i) {
      const double kappa = k[0] - 1 + 2.0 * i / 2000000;
      best = std::min(best, scalar_gamma(k[0], k[1], k[2], k[3], k[4], kappa));
    }
    EXPECT_NEAR(scalar_optimum(k[0], k[1], k[2], k[3], k[4]) / best, 1.0, 1e-9) << "a = " << k[0];
  }
}

TEST(ObserverForm, ScalarPlantsMatchTheClosedFormByLmiAndRiccati) {
  const double cases[][5] = {{1, 1, 1, 1, 1},     {1.2, 0.3, 2, 0.5, 1}, {0.5, 1, 1, 0.2, 2},
                             {-0.7, 1, 1, 1, 1},  {0.3, 0.1, -1, 1, 1},  {-1.5, 1, 1, 0.1, 1},
                             {1, 0.05, 1, 0.1, 1}};
  for (const auto& k : cases) {
    SCOPED_TRACE(testing::Message() << "a=" << k[0] << " b=" << k[1] << " c=" << k[2] << " d=" << k[3]);
    const Plant P = scalar_plant(k[0], k[1], k[2], k[3], k[4]);
    const double closed = scalar_optimum(k[0], k[1], k[2], k[3], k[4]);
    const double riccati = hinf::certify::optimal_hinf_predictor_gamma(P, 1e-10);
    const hinf::synth::SynthesisResult res = hinf::synth::synthesize(P, observer_settings());
    std::printf("  closed form %.12g  Riccati %.12g  LMI %.12g\n", closed, riccati, res.gamma);
    EXPECT_NEAR(riccati / closed, 1.0, 1e-8);
    EXPECT_NEAR(res.gamma / closed, 1.0, 1e-6);
    EXPECT_GE(res.gamma, closed * (1 - 1e-9));  // certified: never below the optimum
    EXPECT_EQ(res.filter.form, FilterForm::Observer);
    EXPECT_TRUE(res.certificate.passed);
  }
}

// The observer-form LMI and the Riccati route agree on γ to 1e-6, and the filter is
// (A − KC, K, L): the recovered realisation is exactly the observer's.
void expect_lmi_equals_riccati(const Plant& P, const char* what) {
  SCOPED_TRACE(what);
  const double riccati = hinf::certify::optimal_hinf_predictor_gamma(P, 1e-10);
  const hinf::synth::SynthesisResult res = hinf::synth::synthesize(P, Settings{});  // auto
  std::printf("  %s: LMI γ = %.12g, Riccati γ = %.12g, rel diff %.2e\n", what, res.gamma, riccati,
              (res.gamma - riccati) / riccati);
  EXPECT_EQ(res.filter.form, FilterForm::Observer);  // auto picks it: A is not Schur stable
  EXPECT_NEAR(res.gamma / riccati, 1.0, 1e-6);
  EXPECT_TRUE(res.certificate.passed);
  EXPECT_LE(hinf::certify::observer_form_mismatch(P, res.filter), 1e-14);
  EXPECT_LT(res.certificate.spectral_radius_nominal, 1.0);
  EXPECT_LE(res.certificate.hinf_norm_nominal, res.gamma);
}

TEST(ObserverForm, DoubleIntegratorMatchesRiccati) { expect_lmi_equals_riccati(double_integrator(0.1, 0.5), "double integrator"); }

TEST(ObserverForm, TripleIntegratorWithKnownInputMatchesRiccati) {
  expect_lmi_equals_riccati(triple_integrator_with_input(), "triple integrator with a known input");
}

// The known input cancels from the error (122): the runtime filter fed u tracks the plant
// driven by u exactly as it tracks the plant without u (same noise, same gain).
TEST(ObserverForm, KnownInputCancelsInTheRuntimeFilter) {
  const Plant P = triple_integrator_with_input();
  const hinf::synth::SynthesisResult res = hinf::synth::synthesize(P, Settings{});
  ASSERT_EQ(res.filter.G_F.cols(), 1);
  hinf::runtime::LtiFilter with_u(res.filter.A_F, res.filter.B_F, res.filter.C_F, res.filter.G_F);
  hinf::runtime::LtiFilter without_u(res.filter.A_F, res.filter.B_F, res.filter.C_F, res.filter.G_F);
  std::mt19937 g(7);
  std::normal_distribution<double> N01;
  VectorXd x_u = VectorXd::Zero(3), x_0 = VectorXd::Zero(3);
  double worst = 0, scale = 0;
  for (int k = 0; k < 4000; ++k) {
    const VectorXd u = VectorXd::Constant(1, 3.0 * std::sin(0.01 * k));  // up to 3 m/s²
    const VectorXd w = VectorXd::Constant(1, N01(g)), v = VectorXd::Constant(1, N01(g));
    const VectorXd e_u = x_u - with_u.step(P.C * x_u + P.D * v, u);
    const VectorXd e_0 = x_0 - without_u.step(P.C * x_0 + P.D * v, VectorXd::Zero(1));
    worst = std::max(worst, (e_u - e_0).norm());
    scale = std::max(scale, x_u.norm());
    x_u = P.A * x_u + P.G * u + P.B * w;
    x_0 = P.A * x_0 + P.B * w;
  }
  std::printf("  |x| up to %.3g, error difference with and without u at most %.3g\n", scale, worst);
  EXPECT_GT(scale, 1e3);                 // the input moved the plant far
  EXPECT_LT(worst, 1e-9 * scale);        // and the error did not notice it
  EXPECT_THROW(with_u.step(VectorXd::Zero(1)), std::invalid_argument);  // u cannot be forgotten
}

hinf::synth::HillPlantSpec uncontrolled_hill(double delta_bar) {
  hinf::synth::HillPlantSpec s;
  s.orbital_rate = 7.2722e-5;
  s.chaser_mass = 1000;
  s.sample_time = 0.1;
  s.delta_bar = delta_bar;
  VectorXd b(6);
  b << 0.05, 0.05, 0.05, 0.001, 0.001, 0.001;
  s.B = b.asDiagonal();
  s.D = 0.1 * MatrixXd::Identity(3, 3);
  return s;
}

TEST(ObserverForm, UncontrolledHillPlantUndiscounted) {
  Plant nominal = hinf::synth::build_hill_plant(uncontrolled_hill(0));
  nominal.G = MatrixXd(6, 0);
  expect_lmi_equals_riccati(nominal, "uncontrolled Hill, nominal");
  // with the orbital-rate uncertainty acting on the error dynamics (123)
  Plant robust = hinf::synth::build_hill_plant(uncontrolled_hill(0.05));
  robust.G = MatrixXd(6, 0);
  const hinf::synth::SynthesisResult res = hinf::synth::synthesize(robust, Settings{});
  EXPECT_EQ(res.filter.form, FilterForm::Observer);
  EXPECT_TRUE(res.certificate.passed);
  EXPECT_TRUE(res.certificate.robust_feasible_at_gamma);
  EXPECT_LT(res.certificate.spectral_radius_sampled_max, 1.0);
  EXPECT_NE(res.bound.find("error dynamics"), std::string::npos) << res.bound;
}

// synthesize(P) must end Infeasible with every one of `parts` in its message.
void expect_infeasible_naming(const Plant& P, std::initializer_list<const char*> parts) {
  try {
    hinf::synth::synthesize(P, Settings{});
    ADD_FAILURE() << "no exception";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::Infeasible);
    for (const char* part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(ObserverForm, UndetectableModeIsNamed) {
  MatrixXd A(2, 2), C(1, 2);
  A << 1.1, 0, 0, 0.5;
  C << 0, 1;  // the unstable mode is not measured
  expect_infeasible_naming(
      certain_plant(A, MatrixXd::Ones(2, 1), C, MatrixXd::Ones(1, 1), MatrixXd::Identity(2, 2)),
      {"λ = 1.1", "not detectable", "v = [1, 0]"});
}

// The direction is reported in the user's coordinates, not the balanced ones: the unstable
// mode of T diag(1.05, 0.5) T⁻¹, T = [1, 0; 2000, 1], is [1, 2000]/‖·‖, and C = [−2000, 1] misses it.
TEST(ObserverForm, UndetectableDirectionIsInTheUsersCoordinates) {
  MatrixXd T(2, 2), C(1, 2);
  T << 1, 0, 2000, 1;
  C << -2000, 1;
  const MatrixXd A = T * Eigen::Vector2d(1.05, 0.5).asDiagonal() * T.inverse();
  expect_infeasible_naming(
      certain_plant(A, MatrixXd::Ones(2, 1), C, MatrixXd::Ones(1, 1), MatrixXd::Identity(2, 2)),
      {"v = [0.0004999999375, 0.999999875]"});
}

TEST(ObserverForm, AugmentedFormOnAnIntegratorSaysWhyAndPointsToTheObserverForm) {
  Settings s;
  s.form = FormChoice::Augmented;
  try {
    hinf::synth::synthesize(double_integrator(0.1, 0.5), s);
    FAIL() << "no exception";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::Infeasible);
    EXPECT_NE(std::string(e.what()).find("observer"), std::string::npos) << e.what();
  }
}

TEST(ObserverForm, StablePlantsStillGetTheAugmentedFilterByDefault) {
  const Plant P = scalar_plant(0.5, 1, 1, 0.2, 2);
  EXPECT_EQ(hinf::synth::synthesize(P, Settings{}).filter.form, FilterForm::Augmented);
  // and both forms reach the same nominal optimum (the central filter is an observer)
  EXPECT_NEAR(hinf::synth::synthesize(P, Settings{}).gamma / hinf::synth::synthesize(P, observer_settings()).gamma,
              1.0, 1e-6);
}

// Invariance (docs/maths.md §4.4): x' = S x of an unstable, detectable random plant gives
// the same γ and the same filter transfer function.
TEST(ObserverForm, SimilarityTwinsOfUnstablePlantsGiveTheSameGamma) {
  std::mt19937 g(2026);
  for (int trial = 0; trial < 3; ++trial) {
    const int n = 4;
    Plant P = certain_plant(hinf::test::random_matrix(g, n, n), hinf::test::random_matrix(g, n, 2),
                            hinf::test::random_matrix(g, 2, n), hinf::test::random_matrix(g, 2, 2),
                            hinf::test::random_matrix(g, 2, n));
    P.A *= 1.3 / P.A.operatorNorm();  // spectral radius up to 1.3: typically unstable
    const MatrixXd S = hinf::test::random_matrix(g, n, n) + 3 * MatrixXd::Identity(n, n);
    const MatrixXd Si = S.inverse();
    Plant Q = P;
    Q.A = S * P.A * Si;
    Q.B = S * P.B;
    Q.C = P.C * Si;
    Q.L = P.L * Si;
    const double gP = hinf::synth::synthesize(P, observer_settings()).gamma;
    const double gQ = hinf::synth::synthesize(Q, observer_settings()).gamma;
    std::printf("  trial %d: γ = %.10g, twin %.10g\n", trial, gP, gQ);
    EXPECT_NEAR(gQ / gP, 1.0, 1e-6) << "trial " << trial;
  }
}

}  // namespace

namespace {

// docs/maths.md (132) for the first-order error system of a scalar observer (127):
// ‖l [b, −k d]/(z − α)‖₂² = l² (b² + k² d²)/(1 − α²).
TEST(H2Norm, FirstOrderClosedForm) {
  const double a = 0.9, b = 0.4, c = 2, d = 0.3, l = 1.5, k = 0.2, alpha = a - k * c;
  hinf::StateSpace s;
  s.A = MatrixXd::Constant(1, 1, alpha);
  s.B = (MatrixXd(1, 2) << b, -k * d).finished();
  s.C = MatrixXd::Constant(1, 1, l);
  s.D = MatrixXd::Zero(1, 2);
  EXPECT_NEAR(hinf::certify::discrete_h2_norm(s) / std::sqrt(l * l * (b * b + k * k * d * d) / (1 - alpha * alpha)), 1.0,
              1e-14);
  s.A(0, 0) = 1.0;
  EXPECT_THROW(hinf::certify::discrete_h2_norm(s), hinf::Error);
}

// The Kalman predictor minimises the RMS error (H2) over all gains, the H∞ filter the
// worst-case gain: each beats the other in its own norm, never in the other's. Scalar
// plants: the Kalman H2 equals a dense scan of (132) over the gain.
TEST(Kalman, EachFilterWinsInItsOwnNorm) {
  for (const Plant& P : {scalar_plant(1, 1, 1, 1, 1), scalar_plant(1.2, 0.3, 2, 0.5, 1), double_integrator(0.1, 0.5),
                         triple_integrator_with_input()}) {
    const hinf::synth::SynthesisResult kf = hinf::synth::kalman_predictor(P, Settings{});
    const hinf::synth::SynthesisResult hi = hinf::synth::synthesize(P, Settings{});
    std::printf("  n=%d: Kalman H2 %.10g gamma %.10g | Hinf H2 %.10g gamma %.10g\n", P.n(),
                kf.certificate.h2_norm_nominal, kf.gamma, hi.certificate.h2_norm_nominal, hi.gamma);
    EXPECT_TRUE(kf.certificate.passed);
    EXPECT_EQ(kf.filter.form, FilterForm::Observer);
    EXPECT_LE(kf.certificate.h2_norm_nominal, hi.certificate.h2_norm_nominal * (1 + 1e-9));
    EXPECT_GE(kf.gamma, hi.gamma * (1 - 1e-9));
    if (P.n() == 1) {
      const double a = P.A(0, 0), b = P.B(0, 0), c = P.C(0, 0), d = P.D(0, 0), l = P.L(0, 0);
      double best = INFINITY;
      for (int i = 1; i < 400000; ++i) {
        const double k = ((a - 1) + 2.0 * i / 400000) / c, alpha = a - k * c;
        best = std::min(best, l * l * (b * b + k * k * d * d) / (1 - alpha * alpha));
      }
      EXPECT_NEAR(kf.certificate.h2_norm_nominal / std::sqrt(best), 1.0, 1e-8);
    }
  }
}

// Exit 3 only with a true certificate (issue 34): the two-mass plant (damped, every mode
// strictly stable) sampled by ZOH at 1e-10 s has its modes at |λ| = 1 − 1e-11; in the
// balanced coordinates a subdiagonal below rounding deflated one to λ = 1 exactly, called
// undetectable. Whatever the synthesis makes of it now, it is not "infeasible".
TEST(ObserverForm, AStableModeSampledAtTenPicosecondsIsNotCalledUndetectable) {
  const std::string config =
      "constants: {c: 0.2}\nparameters:\n  k: {nominal: 1, range: [0.95, 1.05]}\n"
      "system:\n  A: [[0, 0, 1, 0], [0, 0, 0, 1], [-1 - k, k, -c, 0], [k, -k, 0, -c]]\n"
      "  B: [[0, 0], [0, 0], [1, 0], [0, 1]]\n  C: [[0, 1, 0, 0]]\n  D: [[0.1]]\n"
      "  L: [[1, 0, 0, 0], [0, 1, 0, 0]]\n  sample_time: 1e-10\n  discretisation: zoh\n";
  const hinf::synth::SynthConfig cfg = hinf::synth::parse_config(config, "t.yaml");
  try {
    hinf::synth::synthesize(cfg.plant, cfg.settings);
  } catch (const hinf::Error& e) {
    EXPECT_NE(e.code(), hinf::ErrorCode::Infeasible) << e.what();
  }
}

// A zero-order hold beyond working accuracy is refused naming sample_time (at 1e300 s it gave
// Γ = 0 and "the process-noise matrix B is zero", a false exit 3).
TEST(ObserverForm, AZeroOrderHoldBeyondWorkingAccuracyIsRefused) {
  const std::string config =
      "system:\n  A: [[0, 1], [-2, -0.2]]\n  B: [[0], [1]]\n  C: [[1, 0]]\n  D: [[0.1]]\n  L: [[1, 0]]\n"
      "  sample_time: 1e300\n";
  try {
    hinf::synth::parse_config(config, "t.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("system.sample_time = 1e300: T ‖A‖ = "), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(hinf::synth::parse_config(
      "system:\n  A: [[0, 1], [-2, -0.2]]\n  B: [[0], [1]]\n  C: [[1, 0]]\n  D: [[0.1]]\n  L: [[1, 0]]\n"
      "  sample_time: 1e7\n",
      "t.yaml"));
}

}  // namespace
