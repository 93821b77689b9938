// The filtered estimate x̂(k|k) of the observer form (docs/maths.md §18.6): the LMI (142)
// against the a posteriori Riccati route (143), an independent computation of the same
// optimum; a scalar plant against a dense scan of its closed-form H∞ norm over both gains;
// the realisation (140) flown by the runtime against the two-gain recursion written out;
// never worse than the predictor; invariance under state coordinates.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/riccati_filter.hpp"
#include "hinf/common/error.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/synth/hill_plant.hpp"
#include "hinf/synth/synthesis.hpp"
#include "example_plants.hpp"
#include "random_plants.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using hinf::Estimate;
using hinf::FilterForm;
using hinf::Plant;
using hinf::synth::FormChoice;
using hinf::synth::Settings;

using hinf::test::certain_plant;
using hinf::test::triple_integrator_with_input;

using hinf::test::scalar_plant;

Settings filtered_settings() {
  Settings s;
  s.estimate = Estimate::Filtered;
  return s;
}

Plant double_integrator() { return hinf::test::double_integrator(0.1, 0.5); }

Plant uncontrolled_hill_plant(double delta_bar) {
  hinf::synth::HillPlantSpec s;
  s.orbital_rate = 7.2722e-5;
  s.chaser_mass = 1000;
  s.sample_time = 0.1;
  s.delta_bar = delta_bar;
  VectorXd b(6);
  b << 0.05, 0.05, 0.05, 0.001, 0.001, 0.001;
  s.B = b.asDiagonal();
  s.D = 0.1 * MatrixXd::Identity(3, 3);
  Plant P = hinf::synth::build_hill_plant(s);
  P.G = MatrixXd(6, 0);
  return P;
}

// The LMI (142) and the a posteriori Riccati route (143) agree on γ to 1e-6; the filtered
// γ is never above the predictor's; the realisation is (140) exactly; the certificate holds.
void expect_filtered_lmi_equals_riccati(const Plant& P, const std::string& what) {
  SCOPED_TRACE(what);
  const double riccati = hinf::certify::optimal_hinf_predictor_gamma(P, 1e-10, Estimate::Filtered);
  const hinf::synth::SynthesisResult res = hinf::synth::synthesize(P, filtered_settings());
  const double predicted = hinf::certify::optimal_hinf_predictor_gamma(P, 1e-10, Estimate::Predicted);
  std::printf("  %s: filtered LMI γ = %.12g, Riccati γ = %.12g (rel diff %.2e); predictor γ = %.12g\n",
              what.c_str(), res.gamma, riccati, (res.gamma - riccati) / riccati, predicted);
  EXPECT_EQ(res.filter.form, FilterForm::Observer);
  ASSERT_TRUE(res.filter.filtered());
  EXPECT_NEAR(res.gamma / riccati, 1.0, 1e-6);
  EXPECT_LE(riccati, predicted * (1 + 1e-9));
  EXPECT_TRUE(res.certificate.passed);
  EXPECT_LE(hinf::certify::observer_form_mismatch(P, res.filter), 1e-13);
  EXPECT_LE(res.certificate.hinf_norm_nominal, res.gamma);
  EXPECT_NE(res.bound.find("x_hat(k|k)"), std::string::npos) << res.bound;
  // the error system has the feedthrough −L M D from v (141)
  const hinf::StateSpace e = hinf::certify::error_system(P, res.filter);
  EXPECT_LE((e.D.rightCols(P.q()) + P.L * res.filter.M * P.D).norm(), 1e-12 * (1 + e.D.norm()));
}

// docs/maths.md (143) at a level above the optimum: the central filter's certified H∞ norm
// is at most that level (the Riccati route's own claim, checked by the symplectic pencil).
void expect_central_filter_achieves_its_level(const Plant& P, double level) {
  const hinf::certify::HinfPredictorLevel at = hinf::certify::hinf_predictor_at_level(P, level, Estimate::Filtered);
  ASSERT_TRUE(at.feasible) << at.reason;
  ASSERT_TRUE(at.filter.filtered());
  const double norm = hinf::certify::discrete_hinf_norm(hinf::certify::error_system(P, at.filter), 1e-10).norm;
  EXPECT_LE(norm, level * (1 + 1e-9));
}

// (141) for a scalar plant: with α = a − k c, β = n α − (l − n c) k, the error's transfer from
// (w, v) is ((l − n c) b, d (β − n z))/(z − α), whose squared gain is affine over affine in
// cos θ, hence largest at θ = 0 or π:
//     γ(k, n)² = max over s = ±1 of [(l − n c)² b² + d² (β − s n)²] / (1 − s α)²,   |α| < 1.
double scalar_filtered_gamma(double a, double b, double c, double d, double l, double k, double n) {
  const double alpha = a - k * c;
  if (!(std::abs(alpha) < 1)) return INFINITY;
  const double beta = n * alpha - (l - n * c) * k, w = (l - n * c) * b;
  double g2 = 0;
  for (double s : {-1.0, 1.0}) g2 = std::max(g2, (w * w + d * d * (beta - s * n) * (beta - s * n)) / ((1 - s * alpha) * (1 - s * alpha)));
  return std::sqrt(g2);
}

// Minimum over (k, n) by a grid over k ∈ (a − 1, a + 1)/c, n ∈ [−4, 4]·|l/c|, zoomed 30 times.
double scalar_filtered_scan(double a, double b, double c, double d, double l) {
  double k0 = a / c, n0 = 0, hk = 1 / std::abs(c), hn = 4 * std::abs(l / c), best = INFINITY;
  for (int round = 0; round < 30; ++round) {
    double bk = k0, bn = n0;
    const int N = 200;
    for (int i = 0; i <= N; ++i)
      for (int j = 0; j <= N; ++j) {
        const double k = k0 + hk * (2.0 * i / N - 1), n = n0 + hn * (2.0 * j / N - 1);
        const double g = scalar_filtered_gamma(a, b, c, d, l, k, n);
        if (g < best) best = g, bk = k, bn = n;
      }
    k0 = bk, n0 = bn, hk *= 0.25, hn *= 0.25;
  }
  return best;
}

TEST(FilteredEstimate, ScalarPlantsMatchADenseScanByLmiAndRiccati) {
  const double cases[][5] = {{1, 1, 1, 1, 1},    {1.2, 0.3, 2, 0.5, 1}, {0.5, 1, 1, 0.2, 2},
                             {-0.7, 1, 1, 1, 1}, {0.3, 0.1, -1, 1, 1},  {1, 0.05, 1, 0.1, 1}};
  for (const auto& c : cases) {
    SCOPED_TRACE(testing::Message() << "a=" << c[0] << " b=" << c[1] << " c=" << c[2] << " d=" << c[3]);
    const Plant P = scalar_plant(c[0], c[1], c[2], c[3], c[4]);
    const double scan = scalar_filtered_scan(c[0], c[1], c[2], c[3], c[4]);
    const double riccati = hinf::certify::optimal_hinf_predictor_gamma(P, 1e-10, Estimate::Filtered);
    const hinf::synth::SynthesisResult res = hinf::synth::synthesize(P, filtered_settings());
    std::printf("  scan %.12g  Riccati %.12g  LMI %.12g  (predictor %.12g)\n", scan, riccati, res.gamma,
                hinf::certify::optimal_hinf_predictor_gamma(P, 1e-10));
    EXPECT_NEAR(riccati / scan, 1.0, 1e-7);
    EXPECT_NEAR(res.gamma / scan, 1.0, 1e-6);
    EXPECT_GE(res.gamma, scan * (1 - 1e-9));  // certified: never below the optimum
    // and the recovered gains achieve it in the closed form too
    EXPECT_LE(scalar_filtered_gamma(c[0], c[1], c[2], c[3], c[4], res.filter.K(0, 0), res.filter.D_F(0, 0)),
              res.gamma * (1 + 1e-9));
    expect_central_filter_achieves_its_level(P, riccati * 1.01);
  }
}

TEST(FilteredEstimate, IntegratorsAndTheUncontrolledHillPlantMatchRiccati) {
  expect_filtered_lmi_equals_riccati(double_integrator(), "double integrator");
  expect_filtered_lmi_equals_riccati(triple_integrator_with_input(), "triple integrator with a known input");
  expect_filtered_lmi_equals_riccati(uncontrolled_hill_plant(0), "uncontrolled Hill plant");
  expect_central_filter_achieves_its_level(double_integrator(), 2.0);
}

TEST(FilteredEstimate, RandomDetectablePlantsMatchRiccati) {
  std::mt19937 g(414);
  for (int trial = 0; trial < 3; ++trial) {
    const int n = 4, m = 2, l = trial == 2 ? 2 : n;  // L = I, and L with fewer rows than n
    Plant P = certain_plant(hinf::test::random_matrix(g, n, n), hinf::test::random_matrix(g, n, 2),
                            hinf::test::random_matrix(g, m, n), hinf::test::random_matrix(g, m, m),
                            l == n ? MatrixXd(MatrixXd::Identity(n, n)) : hinf::test::random_matrix(g, l, n));
    P.A *= 1.2 / P.A.operatorNorm();
    expect_filtered_lmi_equals_riccati(P, "random n = 4, l = " + std::to_string(l) + ", trial " + std::to_string(trial));
  }
}

// The realisation written, flown by the runtime with its feedthrough, is the two-gain
// recursion (140) written out: x̂(k|k) = x̂ + M(y − C x̂), ẑ = L x̂(k|k), x̂ ← A x̂ + G u + K(y − C x̂).
TEST(FilteredEstimate, RuntimeFliesTheTwoGainRecursion) {
  const Plant P = triple_integrator_with_input();
  const hinf::synth::SynthesisResult res = hinf::synth::synthesize(P, filtered_settings());
  const hinf::Filter& f = res.filter;
  hinf::runtime::LtiFilter flown(f.A_F, f.B_F, f.C_F, f.G_F, f.D_F);
  std::mt19937 g(3);
  std::normal_distribution<double> N01;
  VectorXd x_hat = VectorXd::Zero(3);
  double worst = 0, scale = 0;
  for (int k = 0; k < 2000; ++k) {
    const VectorXd y = VectorXd::Constant(1, 10 * N01(g)), u = VectorXd::Constant(1, N01(g));
    const VectorXd x_filtered = x_hat + f.M * (y - P.C * x_hat);
    const VectorXd z = flown.step(y, u);
    worst = std::max(worst, (z - P.L * x_filtered).norm());
    scale = std::max(scale, z.norm());
    x_hat = P.A * x_hat + P.G * u + f.K * (y - P.C * x_hat);
  }
  std::printf("  |z| up to %.3g, runtime vs (140) at most %.3g\n", scale, worst);
  EXPECT_LT(worst, 1e-11 * scale);
  EXPECT_THROW(hinf::runtime::LtiFilter(f.A_F, f.B_F, f.C_F, f.G_F, MatrixXd::Zero(2, 1)), std::invalid_argument);
}

TEST(FilteredEstimate, SimilarityTwinsGiveTheSameGamma) {
  std::mt19937 g(2027);
  const int n = 4;
  Plant P = certain_plant(hinf::test::random_matrix(g, n, n), hinf::test::random_matrix(g, n, 2),
                          hinf::test::random_matrix(g, 2, n), hinf::test::random_matrix(g, 2, 2),
                          hinf::test::random_matrix(g, 2, n));
  P.A *= 1.3 / P.A.operatorNorm();
  const MatrixXd S = hinf::test::random_matrix(g, n, n) + 3 * MatrixXd::Identity(n, n), Si = S.inverse();
  Plant Q = P;
  Q.A = S * P.A * Si;
  Q.B = S * P.B;
  Q.C = P.C * Si;
  Q.L = P.L * Si;
  const double gP = hinf::synth::synthesize(P, filtered_settings()).gamma;
  const double gQ = hinf::synth::synthesize(Q, filtered_settings()).gamma;
  std::printf("  γ = %.10g, twin %.10g\n", gP, gQ);
  EXPECT_NEAR(gQ / gP, 1.0, 1e-6);
}

TEST(FilteredEstimate, DependentRowsOfLAreRefusedNamingThem) {
  Plant P = double_integrator();
  P.L = MatrixXd::Ones(2, 2);  // rank 1
  try {
    hinf::synth::synthesize(P, filtered_settings());
    FAIL() << "no exception";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("rank 1 < 2"), std::string::npos) << e.what();
  }
}

// The Kalman filter x̂(k|k) (143) at γ = ∞: its RMS error is at most the Kalman predictor's
// (it has y(k) too), and the H∞ filtered estimate beats it in γ.
TEST(FilteredEstimate, KalmanFilterBesideTheHinfFilteredEstimate) {
  const Plant P = double_integrator();
  const hinf::synth::SynthesisResult kf = hinf::synth::kalman_predictor(P, filtered_settings());
  const hinf::synth::SynthesisResult kp = hinf::synth::kalman_predictor(P, Settings{});
  const hinf::synth::SynthesisResult hf = hinf::synth::synthesize(P, filtered_settings());
  std::printf("  Kalman filter H2 %.10g gamma %.10g | predictor H2 %.10g | Hinf filtered H2 %.10g gamma %.10g\n",
              kf.certificate.h2_norm_nominal, kf.gamma, kp.certificate.h2_norm_nominal,
              hf.certificate.h2_norm_nominal, hf.gamma);
  EXPECT_TRUE(kf.filter.filtered());
  EXPECT_TRUE(kf.certificate.passed);
  EXPECT_LE(kf.certificate.h2_norm_nominal, kp.certificate.h2_norm_nominal);
  EXPECT_LE(kf.certificate.h2_norm_nominal, hf.certificate.h2_norm_nominal * (1 + 1e-9));
  EXPECT_GE(kf.gamma, hf.gamma * (1 - 1e-9));
}

// With uncertainty (on the error dynamics, (141) with A + H F E − K C): the robust bound by the
// analysis LMI (50) solved by the barrier method equals check 4's bounded-real search, both
// with the feedthrough −L M D v; the Kalman filter x̂(k|k) of the uncertain plant is certified at it.
TEST(FilteredEstimate, UncertainPlantRobustBoundTwoWays) {
  const Plant P = uncontrolled_hill_plant(0.05);
  const hinf::synth::SynthesisResult res = hinf::synth::synthesize(P, filtered_settings());
  ASSERT_TRUE(res.certificate.passed);
  EXPECT_TRUE(res.certificate.robust_feasible_at_gamma);
  const double lmi = hinf::synth::robust_bound(P, res.filter, filtered_settings());
  std::printf("  γ = %.12g, bounded-real bound %.12g, analysis-LMI bound %.12g\n", res.gamma,
              res.certificate.robust_bound, lmi);
  EXPECT_NEAR(lmi / res.certificate.robust_bound, 1.0, 1e-6);
  const hinf::synth::SynthesisResult kf = hinf::synth::kalman_predictor(P, filtered_settings());
  EXPECT_TRUE(kf.certificate.passed);
  EXPECT_NEAR(hinf::synth::robust_bound(P, kf.filter, filtered_settings()) / kf.certificate.robust_bound, 1.0, 1e-6);
  EXPECT_GE(kf.gamma, res.gamma);
}

}  // namespace
