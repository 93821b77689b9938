// The Hill/CW plant builder (docs/maths.md §9.4–§9.5) against closed forms: the scalar CW equations,
// the exact uncertain discrete A, Taylor bounds of the matrix exponential.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>
#include <string>

#include "hinf/synth/config.hpp"
#include "hinf/synth/hill_plant.hpp"
#include "hinf/common/error.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using hinf::synth::HillPlantSpec;

constexpr double kOmega0 = 7.2722e-5;  // docs/maths.md §9.8 table
constexpr double kMass = 1000;
constexpr double kT = 0.1;

// K of docs/maths.md (77), typed here independently of configs/paper-*.yaml.
MatrixXd paper_K() {
  MatrixXd K(3, 6);
  K << -2.2541, -0.0071, -0.0072, -22.3975, 2.3256, 1.9369,  //
      -0.0104, -2.2493, -0.0055, 2.3259, -23.7456, 1.4544,   //
      -0.0072, -0.0055, -2.2471, 1.9357, 1.4552, -24.2818;
  return K;
}

HillPlantSpec paper_model(double delta_bar, hinf::models::Discretisation d) {
  HillPlantSpec m;
  m.orbital_rate = kOmega0;
  m.chaser_mass = kMass;
  m.K = paper_K();
  m.sample_time = kT;
  m.delta_bar = delta_bar;
  m.discretisation = d;
  VectorXd b(6);
  b << 0.05, 0.05, 0.05, 0.001, 0.001, 0.001;
  m.B = b.asDiagonal();
  m.D = 0.1 * MatrixXd::Identity(3, 3);
  return m;  // C, L empty: the paper's defaults
}

// ẋ from the scalar CW equations docs/maths.md (62) with u = K x:
//   ẍ = 3ω²x + 2ωẏ + F_x/m,  ÿ = −2ωẋ + F_y/m,  z̈ = −ω²z + F_z/m.
VectorXd cw_rhs(const VectorXd& s, double w, double m, const MatrixXd& K) {
  const VectorXd u = K * s;
  VectorXd d(6);
  d << s(3), s(4), s(5), 3 * w * w * s(0) + 2 * w * s(4) + u(0) / m,
      -2 * w * s(3) + u(1) / m, -w * w * s(2) + u(2) / m;
  return d;
}

// The continuous closed-loop matrix, column by column from the scalar equations.
MatrixXd cw_closed_loop(double w, double m, const MatrixXd& K) {
  MatrixXd A(6, 6);
  for (int i = 0; i < 6; ++i) A.col(i) = cw_rhs(VectorXd::Unit(6, i), w, m, K);
  return A;
}

double norm1(const MatrixXd& M) { return M.cwiseAbs().colwise().sum().maxCoeff(); }

TEST(HillModel, ContinuousAMatchesScalarCwEquations) {
  for (double w : {kOmega0, 1.1e-3, 0.0, -3e-4}) {
    const MatrixXd A1 = hinf::models::hill::continuous_A(w);
    const MatrixXd expected = cw_closed_loop(w, 1.0, MatrixXd::Zero(3, 6));
    EXPECT_EQ((A1 - expected).cwiseAbs().maxCoeff(), 0.0) << "omega = " << w;
  }
  // A few entries written out: A₁(4,1) = 3ω², A₁(4,5) = 2ω, A₁(5,4) = −2ω, A₁(6,3) = −ω².
  const double w = 2e-3;
  const MatrixXd A1 = hinf::models::hill::continuous_A(w);
  EXPECT_DOUBLE_EQ(A1(3, 0), 1.2e-5);
  EXPECT_DOUBLE_EQ(A1(3, 4), 4e-3);
  EXPECT_DOUBLE_EQ(A1(4, 3), -4e-3);
  EXPECT_DOUBLE_EQ(A1(5, 2), -4e-6);
  EXPECT_EQ(A1(0, 3), 1.0);
  EXPECT_EQ(A1(2, 5), 1.0);
  EXPECT_EQ(A1.topLeftCorner(3, 3).cwiseAbs().maxCoeff(), 0.0);
}

TEST(HillModel, InputMatrixIsZeroOverIdentityOverMass) {
  const MatrixXd G0 = hinf::models::hill::input_matrix(250.0);
  ASSERT_EQ(G0.rows(), 6);
  ASSERT_EQ(G0.cols(), 3);
  EXPECT_EQ(G0.topRows(3).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_TRUE(G0.bottomRows(3).isApprox(MatrixXd::Identity(3, 3) * 0.004, 0.0));
}

TEST(HillModel, EulerDiscreteAIsIdentityPlusTTimesClosedLoop) {
  const auto plant = hinf::synth::build_hill_plant(paper_model(0.05, hinf::models::Discretisation::Euler));
  const MatrixXd expected = MatrixXd::Identity(6, 6) + kT * cw_closed_loop(kOmega0, kMass, paper_K());
  EXPECT_LE((plant.A - expected).cwiseAbs().maxCoeff(), 4.5e-16);  // a few ulps of 1
  // Entries by hand: A(1,4) = T; A(4,4) = 1 + T K(1,4)/m; A(4,5) = T(2ω₀ + K(1,5)/m).
  EXPECT_DOUBLE_EQ(plant.A(0, 3), 0.1);
  EXPECT_DOUBLE_EQ(plant.A(3, 3), 1 + 0.1 * -22.3975 / 1000);
  EXPECT_DOUBLE_EQ(plant.A(3, 4), 0.1 * (2 * kOmega0 + 2.3256 / 1000));
  EXPECT_DOUBLE_EQ(plant.A(5, 2), 0.1 * (-kOmega0 * kOmega0 + -2.2471 / 1000));
  // Paper defaults: C = [I₃ 0₃], L = I₆; B, D as given.
  MatrixXd C = MatrixXd::Zero(3, 6);
  C.leftCols(3).setIdentity();
  EXPECT_EQ(plant.C, C);
  EXPECT_EQ(plant.L, MatrixXd::Identity(6, 6));
  EXPECT_EQ(plant.D, 0.1 * MatrixXd::Identity(3, 3));
}

TEST(HillModel, UncertaintyFactorsAreTheSpecsHaAndEa) {
  const double dbar = 0.05;
  const auto plant = hinf::synth::build_hill_plant(paper_model(dbar, hinf::models::Discretisation::Euler));
  MatrixXd Ha = MatrixXd::Zero(6, 6);
  Ha(3, 0) = 3 * kOmega0;
  Ha(3, 4) = 2;
  Ha(4, 3) = -2;
  Ha(5, 2) = -kOmega0;
  VectorXd ea(6);
  const double q = kOmega0 * (2 * dbar + dbar * dbar);
  ea << q, 0, q, kOmega0 * dbar, kOmega0 * dbar, 0;  // E_a(4,4) = ω₀δ̄ (docs/maths.md §16, item 3)
  EXPECT_LE((plant.H - kT * Ha).cwiseAbs().maxCoeff(), 1e-18);
  EXPECT_LE((plant.E - MatrixXd(ea.asDiagonal())).cwiseAbs().maxCoeff(), 1e-20);
  EXPECT_EQ(plant.j(), 6);
  EXPECT_EQ(plant.k(), 6);
}

// ΔA = T(A₁(ω₀(1+δ)) − A₁(ω₀)) = H F(δ) E exactly (euler), for δ in [−δ̄, δ̄] incl. ±δ̄.
TEST(HillModel, EulerUncertaintyIsExactForAdmissibleDelta) {
  for (double dbar : {0.05, 1.0, 2.5}) {
    const HillPlantSpec model = paper_model(dbar, hinf::models::Discretisation::Euler);
    const auto plant = hinf::synth::build_hill_plant(model);
    for (double frac : {-1.0, -0.7, -0.5, -0.1, 0.0, 1e-3, 0.3, 0.9, 1.0}) {
      const double delta = frac * dbar;
      const MatrixXd F = hinf::synth::hill_uncertainty_F(delta, dbar);
      EXPECT_LE(F.cwiseAbs().maxCoeff(), 1.0 + 1e-15) << "F must satisfy FᵀF ≤ I";
      const MatrixXd HFE = plant.H * F * plant.E;
      // closed form of T·ΔA₁ (1-based): (4,1) 3ω₀²(2δ+δ²), (4,5) 2ω₀δ, (5,4) −2ω₀δ, (6,3) −ω₀²(2δ+δ²)
      MatrixXd dA = MatrixXd::Zero(6, 6);
      const double w2 = kOmega0 * kOmega0 * (2 * delta + delta * delta);
      dA(3, 0) = kT * 3 * w2;
      dA(3, 4) = kT * 2 * kOmega0 * delta;
      dA(4, 3) = -kT * 2 * kOmega0 * delta;
      dA(5, 2) = -kT * w2;
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c)
          EXPECT_NEAR(HFE(r, c), dA(r, c), 1e-14 * std::abs(dA(r, c)) + 1e-300)
              << "dbar " << dbar << " delta " << delta << " entry " << r << "," << c;
      // and against the exact uncertain discrete A (the entries ω touches are ~1e-3: rounding ~1e-19)
      const MatrixXd exact = hinf::synth::hill_exact_discrete_A(model, delta);
      EXPECT_LE((exact - (plant.A + HFE)).cwiseAbs().maxCoeff(), 1e-18)
          << "dbar " << dbar << " delta " << delta;
    }
  }
}

TEST(HillModel, FIsNormOneAtTheVerticesAndRefusedOutside) {
  for (double dbar : {0.05, 1.0}) {
    for (double delta : {-dbar, dbar}) {
      const MatrixXd F = hinf::synth::hill_uncertainty_F(delta, dbar);
      const double norm = Eigen::JacobiSVD<MatrixXd>(F).singularValues()(0);
      EXPECT_NEAR(norm, 1.0, 1e-15);
    }
  }
  try {
    hinf::synth::hill_uncertainty_F(0.06, 0.05);
    FAIL() << "delta outside [-delta_bar, delta_bar] accepted";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("0.06"), std::string::npos) << e.what();
  }
}

TEST(HillModel, ZeroDeltaBarMeansNoUncertainty) {
  const auto plant = hinf::synth::build_hill_plant(paper_model(0.0, hinf::models::Discretisation::Euler));
  EXPECT_FALSE(plant.uncertain());
  EXPECT_EQ(plant.H.rows(), 6);
  EXPECT_EQ(plant.H.cols(), 0);
  EXPECT_EQ(plant.E.rows(), 0);
  EXPECT_EQ(plant.E.cols(), 6);
}

// exp(T A_c) = I + T A_c + T² A_c²/2 + R,  ‖R‖ ≤ (T‖A_c‖)³/6 · e^{T‖A_c‖};
// Γ = ∫₀ᵀ e^{A_c s} ds = T I + T² A_c/2 + R', ‖R'‖ ≤ T³‖A_c‖²/6 · e^{T‖A_c‖}.
TEST(HillModel, ZohAgreesWithTaylorSeriesAndWithEulerToSecondOrder) {
  for (double T : {0.1, 0.01, 1.0}) {
    HillPlantSpec ze = paper_model(0.05, hinf::models::Discretisation::ZeroOrderHold);
    HillPlantSpec eu = paper_model(0.05, hinf::models::Discretisation::Euler);
    ze.sample_time = eu.sample_time = T;
    const auto pz = hinf::synth::build_hill_plant(ze);
    const auto pe = hinf::synth::build_hill_plant(eu);
    const MatrixXd Ac = cw_closed_loop(kOmega0, kMass, paper_K());
    const double a = norm1(Ac);
    const MatrixXd I = MatrixXd::Identity(6, 6);
    const double rounding = 1e-14;
    EXPECT_LE(norm1(pz.A - (I + T * Ac + T * T / 2 * Ac * Ac)),
              std::pow(T * a, 3) / 6 * std::exp(T * a) + rounding) << "T = " << T;
    // zoh − euler = T²A_c²/2 + O(T³): second order in T
    EXPECT_LE(norm1(pz.A - pe.A), T * T / 2 * a * a + std::pow(T * a, 3) / 6 * std::exp(T * a) + rounding);
    const MatrixXd Ha = hinf::models::hill::uncertainty_H_a(kOmega0);
    const MatrixXd Gamma_series_H = (T * I + T * T / 2 * Ac) * Ha;
    EXPECT_LE(norm1(pz.H - Gamma_series_H),
              std::pow(T, 3) * a * a / 6 * std::exp(T * a) * norm1(Ha) + rounding) << "T = " << T;
    EXPECT_EQ(pz.E, pe.E);
  }
}

// The zoh uncertainty model is first order (hill_model.hpp): the residual against the
// exact exp(T(A_c + ΔA₁)) obeys ‖R‖ ≤ e^{2aT} a d T²/2 + (T d)²/2 e^{T(a+d)}, a = ‖A_c‖, d = ‖ΔA₁‖.
TEST(HillModel, ZohUncertaintyModelIsFirstOrderAccurate) {
  for (double dbar : {0.05, 1.0}) {
    const HillPlantSpec model = paper_model(dbar, hinf::models::Discretisation::ZeroOrderHold);
    const auto plant = hinf::synth::build_hill_plant(model);
    const MatrixXd Ac = cw_closed_loop(kOmega0, kMass, paper_K());
    const double a = norm1(Ac);
    for (double frac : {-1.0, -0.5, 0.5, 1.0}) {
      const double delta = frac * dbar;
      const MatrixXd exact = hinf::synth::hill_exact_discrete_A(model, delta);
      const MatrixXd dA1 = hinf::models::hill::continuous_A(kOmega0 * (1 + delta)) -
                           hinf::models::hill::continuous_A(kOmega0);
      const double d = norm1(dA1);
      const MatrixXd model_A = plant.A + plant.H * hinf::synth::hill_uncertainty_F(delta, dbar) * plant.E;
      const double bound = std::exp(2 * a * kT) * a * d * kT * kT / 2 +
                           std::pow(kT * d, 2) / 2 * std::exp(kT * (a + d));
      EXPECT_LE(norm1(exact - model_A), bound + 1e-15) << "dbar " << dbar << " delta " << delta;
      // and the model captures ΔA to first order: the residual is far below ‖ΔA‖ itself
      EXPECT_LE(norm1(exact - model_A), 0.05 * norm1(exact - plant.A));
    }
  }
}

// The library names the HillPlantSpec field (Error::key() too); the config reader
// re-keys it to hill.<field> (test_config.cpp, cli tests).
TEST(HillModel, AbsurdPhysicalValuesAreRefusedNamingFieldAndValue) {
  struct Case {
    void (*mutate)(HillPlantSpec&);
    const char* field;
    const char* fragment;
  };
  const Case cases[] = {
      {[](HillPlantSpec& m) { m.chaser_mass = -5; }, "chaser_mass", "chaser_mass = -5"},
      {[](HillPlantSpec& m) { m.chaser_mass = 0; }, "chaser_mass", "chaser_mass = 0"},
      {[](HillPlantSpec& m) { m.chaser_mass = 4.9e-324; }, "chaser_mass", "chaser_mass = 5e-324: too small"},
      {[](HillPlantSpec& m) { m.sample_time = 0; }, "sample_time", "sample_time = 0"},
      {[](HillPlantSpec& m) { m.orbital_rate = -1e-4; }, "orbital_rate", "orbital_rate = -0.0001"},
      {[](HillPlantSpec& m) { m.orbital_rate = INFINITY; }, "orbital_rate", "orbital_rate = inf"},
      {[](HillPlantSpec& m) { m.delta_bar = 10; }, "delta_bar", "delta_bar = 10"},
      {[](HillPlantSpec& m) { m.delta_bar = -0.1; }, "delta_bar", "delta_bar = -0.1"},
      {[](HillPlantSpec& m) { m.delta_bar = NAN; }, "delta_bar", "delta_bar = nan"},
      {[](HillPlantSpec& m) { m.K = MatrixXd::Zero(3, 5); }, "K", "K: expected 3x6"},
      {[](HillPlantSpec& m) { m.B = MatrixXd::Zero(5, 5); }, "B", "B: expected 6 rows"},
      {[](HillPlantSpec& m) { m.D = MatrixXd::Zero(2, 2); }, "D", "D: expected 3 rows (m from C)"},
      {[](HillPlantSpec& m) { m.L = MatrixXd::Zero(6, 5); }, "L", "L: expected 6 columns"},
      {[](HillPlantSpec& m) { m.K(1, 2) = NAN; }, "K", "K: entry (2, 3) = nan"},
  };
  // ZOH only: exp(A_c·T) overflows (Euler's I + A_c·T stays finite and is refused as not
  // Schur stable, exit 3, by the synthesis's pre-flight).
  std::vector<Case> all(std::begin(cases), std::end(cases));
  all.push_back({[](HillPlantSpec& m) {
                   m.sample_time = 1e300;
                   m.discretisation = hinf::models::Discretisation::ZeroOrderHold;
                 },
                 "sample_time", "sample_time = 1e300: the discrete Hill model"});
  for (const auto discretisation : {hinf::models::Discretisation::Euler, hinf::models::Discretisation::ZeroOrderHold}) {
    for (const Case& c : all) {
      HillPlantSpec m = paper_model(0.05, discretisation);
      c.mutate(m);
      try {
        hinf::synth::build_hill_plant(m);
        ADD_FAILURE() << "accepted: " << c.fragment;
      } catch (const hinf::Error& e) {
        EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput) << e.what();
        EXPECT_EQ(e.key(), c.field) << e.what();
        EXPECT_EQ(std::string(e.what()).rfind(c.fragment, 0), 0u)
            << "message '" << e.what() << "' does not start with '" << c.fragment << "'";
      }
    }
  }
}

// Both paper configs load with the dimensions of docs/maths.md §9.8 and a Schur-stable nominal A.
TEST(HillModel, PaperConfigsLoadWithPaperDimensions) {
  for (const char* name : {"paper-dbar0.05.yaml", "paper-dbar1.yaml"}) {
    const std::string path = std::string(HINF_SOURCE_DIR) + "/configs/" + name;
    const auto cfg = hinf::synth::load_config(path);
    const auto& P = cfg.plant;
    EXPECT_EQ(P.n(), 6);
    EXPECT_EQ(P.p(), 6);
    EXPECT_EQ(P.m(), 3);
    EXPECT_EQ(P.q(), 3);
    EXPECT_EQ(P.l(), 6);
    EXPECT_EQ(P.j(), 6);
    EXPECT_EQ(P.k(), 6);
    ASSERT_TRUE(cfg.hill.has_value());
    EXPECT_EQ(cfg.hill->K, paper_K()) << "K in " << name << " differs from docs/maths.md (77)";
    EXPECT_EQ(cfg.hill->discretisation, hinf::models::Discretisation::Euler);
    const double dbar = std::string(name) == "paper-dbar1.yaml" ? 1.0 : 0.05;
    EXPECT_EQ(cfg.hill->delta_bar, dbar);
    const auto reference = hinf::synth::build_hill_plant(paper_model(dbar, hinf::models::Discretisation::Euler));
    EXPECT_EQ(P.A, reference.A);
    EXPECT_EQ(P.B, reference.B);
    EXPECT_EQ(P.C, reference.C);
    EXPECT_EQ(P.D, reference.D);
    EXPECT_EQ(P.L, reference.L);
    EXPECT_EQ(P.H, reference.H);
    EXPECT_EQ(P.E, reference.E);
    const double rho = P.A.eigenvalues().cwiseAbs().maxCoeff();
    std::printf("[ info     ] %s: spectral radius of A = %.12f\n", name, rho);
    EXPECT_LT(rho, 1.0);
  }
}

}  // namespace
