// Properties of the synthesis solver that have closed forms or exact invariances:
// duality gap bracket, invariance under H ← cH, E ← E/c (the balance must be undone
// exactly), homogeneity of γ in (B, D) and in L, determinism, and the pre-flight
// refusal of plants that are not (robustly) Schur stable.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <complex>
#include <random>
#include <string>

#include "hinf/synth/config.hpp"
#include "hinf/common/error.hpp"
#include "hinf/synth/synthesis.hpp"
#include "random_plants.hpp"

namespace {

using Eigen::MatrixXd;
using hinf::Plant;
using hinf::synth::Settings;

Plant example_plant() {
  return hinf::synth::load_config(std::string(HINF_SOURCE_DIR) + "/configs/example-matrices.yaml").plant;
}

Plant random_uncertain_plant(unsigned seed, int n) {
  using hinf::test::random_matrix;
  std::mt19937 g(seed);
  Plant P;
  P.A = random_matrix(g, n, n);
  P.A *= 0.7 / P.A.operatorNorm();
  P.B = random_matrix(g, n, 2);
  P.C = random_matrix(g, 2, n);
  P.D = 0.2 * random_matrix(g, 2, 2);
  P.L = random_matrix(g, 2, n);
  P.H = random_matrix(g, n, 2);
  P.H *= 0.5 / P.H.operatorNorm();
  P.E = random_matrix(g, 1, n);
  P.E *= 0.4 / P.E.operatorNorm();  // ‖A‖ + ‖H‖‖E‖ = 0.9 < 1
  return P;
}

TEST(Solver, GapBracketAndCertificate) {
  for (unsigned seed : {1u, 2u}) {
    const Plant P = random_uncertain_plant(seed, 3 + static_cast<int>(seed));
    const Settings st;
    const auto r = hinf::synth::synthesize(P, st);
    EXPECT_LE(r.solver.dual_bound_gamma_squared, r.gamma_squared);
    EXPECT_GT(r.solver.dual_bound_gamma_squared, 0.0);
    // the certified gap meets the tolerance; the written γ² may be the optimum's value
    // times (1 + relative_gap_tol) (synthesize's retry of check 4), hence 2·tol
    EXPECT_LE(r.solver.relative_gap, st.solver.relative_gap_tol);
    EXPECT_LE(r.gamma_squared - r.solver.dual_bound_gamma_squared, 2 * st.solver.relative_gap_tol * r.gamma_squared)
        << "gap larger than relative_gap_tol promises";
    EXPECT_NEAR(r.gamma * r.gamma, r.gamma_squared, 1e-14 * r.gamma_squared);
    EXPECT_TRUE(r.certificate.passed);
    EXPECT_LE(r.certificate.hinf_norm_nominal, r.gamma);
    EXPECT_LE(r.certificate.robust_bound, r.gamma * (1 + 1e-12));
    EXPECT_EQ(r.solver.lmi_order, 4 * P.n() + P.p() + P.q() + P.l() + P.j());
  }
}

// ΔA = HFE is unchanged by H ← cH, E ← E/c: γ* must not move.
TEST(Solver, InvariantUnderHEScaling) {
  const Plant P = random_uncertain_plant(7, 4);
  const double g0 = hinf::synth::synthesize(P, Settings{}).gamma;
  for (double c : {1e-3, 1e4}) {
    Plant Q = P;
    Q.H *= c;
    Q.E /= c;
    const double g1 = hinf::synth::synthesize(Q, Settings{}).gamma;
    EXPECT_NEAR(g1, g0, 2e-6 * g0) << "c = " << c;
  }
}

// e and τ are linear: (B, D) ← α(B, D) scales the optimal γ by α; L ← βL scales it by β.
TEST(Solver, GammaHomogeneous) {
  const Plant P = example_plant();
  const double g0 = hinf::synth::synthesize(P, Settings{}).gamma;
  Plant Q = P;
  Q.B *= 3.0;
  Q.D *= 3.0;
  EXPECT_NEAR(hinf::synth::synthesize(Q, Settings{}).gamma, 3.0 * g0, 3e-6 * g0);
  Plant R = P;
  R.L *= 0.25;
  EXPECT_NEAR(hinf::synth::synthesize(R, Settings{}).gamma, 0.25 * g0, 0.25 * 2e-6 * g0);
}

TEST(Solver, Deterministic) {
  const Plant P = random_uncertain_plant(3, 3);
  const auto a = hinf::synth::synthesize(P, Settings{});
  const auto b = hinf::synth::synthesize(P, Settings{});
  EXPECT_EQ(a.gamma, b.gamma);
  EXPECT_TRUE(a.filter.A_F == b.filter.A_F);
  EXPECT_TRUE(a.filter.B_F == b.filter.B_F);
  EXPECT_TRUE(a.filter.C_F == b.filter.C_F);
  EXPECT_EQ(a.solver.newton_iterations, b.solver.newton_iterations);
}

void expect_infeasible(const Plant& P, const std::string& must_contain, const std::string& number,
                       const Settings& settings = Settings{}) {
  try {
    (void)hinf::synth::synthesize(P, settings);
    FAIL() << "no error for an ill-posed plant";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::Infeasible) << e.what();
    const std::string msg = e.what();
    EXPECT_NE(msg.find(must_contain), std::string::npos) << msg;
    EXPECT_NE(msg.find(number), std::string::npos) << msg << "\n(expected the value " << number << ")";
  }
}

TEST(Solver, UnstablePlantRefusedWithSpectralRadius) {
  Plant P = example_plant();
  P.A << 1.05, 0.0, 0.3, 0.5;  // eigenvalues 1.05 and 0.5
  Settings augmented;  // Theorem 1's filter does not exist; the observer form does (docs/maths.md §18)
  augmented.form = hinf::synth::FormChoice::Augmented;
  expect_infeasible(P, "spectral radius", "1.05", augmented);
  EXPECT_EQ(hinf::synth::synthesize(P, Settings{}).filter.form, hinf::FilterForm::Observer);
}

TEST(Solver, NotRobustlyStableRefused) {
  Plant P = example_plant();
  P.A << 0.9, 0.0, 0.0, 0.5;
  P.H = MatrixXd::Zero(2, 1);
  P.H(0, 0) = 1.0;
  P.E = MatrixXd::Zero(1, 2);
  P.E(0, 0) = 0.2;  // F = 1: eigenvalue 1.1
  Settings augmented;  // the augmented filter's verdict; auto goes on to the observer form
  augmented.form = hinf::synth::FormChoice::Augmented;
  expect_infeasible(P, "robustly", "1.1", augmented);
  // auto: the observer form, whose uncertainty acts on the error dynamics, and why
  const hinf::synth::SynthesisResult r = hinf::synth::synthesize(P, Settings{});
  EXPECT_EQ(r.filter.form, hinf::FilterForm::Observer);
  EXPECT_TRUE(r.certificate.passed);
  EXPECT_NE(r.augmented_infeasible.find("not robustly Schur stable"), std::string::npos) << r.augmented_infeasible;
}

// The same uncertainty on the mode y does not see: no observer form either (e₁'s pole 0.9 + 0.2 F
// reaches 1.1 for every K). Auto reports both forms' outcomes; the augmented verdict alone is not
// a verdict about auto, so the exit is the observer form's (no verified certificate there).
TEST(Solver, AutoWhereNeitherFormExistsNamesBoth) {
  Plant P = example_plant();
  P.A << 0.9, 0.0, 0.0, 0.5;
  P.C << 0, 1;
  P.H = MatrixXd::Zero(2, 1);
  P.H(0, 0) = 1.0;
  P.E = MatrixXd::Zero(1, 2);
  P.E(0, 0) = 0.2;
  try {
    (void)hinf::synth::synthesize(P, Settings{});
    FAIL() << "a filter for a plant without one";
  } catch (const hinf::Error& e) {
    EXPECT_NE(e.code(), hinf::ErrorCode::Ok);
    const std::string msg = e.what();
    EXPECT_NE(msg.find("Theorem 1's augmented filter: plant is not robustly Schur stable"), std::string::npos) << msg;
    EXPECT_NE(msg.find("the observer form"), std::string::npos) << msg;
  }
}

}  // namespace

// The interruption hook (sdp::Options::interrupted, a front end's Ctrl-C): once it answers
// true the synthesis ends with a numerical failure that says so, after at most a few more
// polls; never polled true, it changes nothing.
TEST(Solver, AnInterruptedSolveEndsSayingSo) {
  const Plant P = random_uncertain_plant(3, 6);
  Settings st;
  int polls = 0;
  st.solver.interrupted = [&polls] { return ++polls > 20; };
  try {
    hinf::synth::synthesize(P, st);
    FAIL() << "an interrupted solve returned";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::NumericalFailure);
    EXPECT_NE(std::string(e.what()).find("interrupted"), std::string::npos) << e.what();
  }
  Settings never;
  never.solver.interrupted = [] { return false; };
  EXPECT_EQ(hinf::synth::synthesize(P, never).gamma, hinf::synth::synthesize(P, Settings()).gamma);
}
