// Output-feedback H∞ controller synthesis (docs/maths.md §26) against independent references:
//  - continuous time: the Doyle–Glover–Khargonekar–Francis γ-iteration (two Hamiltonian
//    Riccati equations and the coupling ρ(X∞Y∞) < γ², Zhou–Doyle–Glover Thm 16.4), on
//    plants in its normalised form (D11 = 0, D12ᵀ[C1 D12] = [0 I], D21[B1ᵀ D21ᵀ] = [0 I]),
//    written here with Eigen only (the stable subspaces by the matrix sign function);
//  - discrete time: the filtering problem as a control problem (u = z_F, D12 = −I, B2 = 0):
//    its optimal γ is the a priori (strictly proper controller) or a posteriori (proper
//    controller) H∞ filter's, from the project's Riccati route (certify/riccati_filter.hpp).
// And the certificate is recomputed from the controller alone: closed-loop stability and
// ‖T_zw‖∞ ≤ γ (1 + 1e-6) by the pencil.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <random>

#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/riccati_filter.hpp"
#include "hinf/models/controller.hpp"
#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/controller_synthesis.hpp"
#include "hinf/synth/api.hpp"
#include "scratch_dir.hpp"
#include "random_plants.hpp"

namespace {

using Eigen::MatrixXd;
using hinf::GeneralisedPlant;
using hinf::TimeDomain;

// ---------------------------------------------------------------- DGKF reference
// sign(H) by Newton's iteration with determinant scaling (H without imaginary-axis
// eigenvalues); false if it does not converge.
bool matrix_sign(const MatrixXd& H, MatrixXd& Z) {
  Z = H;
  const double n = static_cast<double>(H.rows());
  double last_change = INFINITY;
  for (int it = 0; it < 100; ++it) {
    const Eigen::PartialPivLU<MatrixXd> lu(Z);
    const double c = std::pow(std::abs(lu.determinant()), 1.0 / n);
    if (!(c > 0) || !std::isfinite(c)) return false;
    const MatrixXd next = 0.5 * (Z / c + c * lu.inverse());
    const double change = (next - Z).norm() / next.norm();
    Z = next;
    // converged, or at its round-off floor (the change stopped falling once small)
    if (change < 1e-14 || (change < 1e-8 && change >= last_change)) return true;
    last_change = change;
  }
  return false;
}

// X = Ric(H): the stabilising solution from the stable invariant subspace [X1; X2] of the
// 2n×2n Hamiltonian H, X = X2 X1⁻¹; false if it does not exist (imaginary-axis
// eigenvalues, X1 singular) or is not positive semidefinite.
bool riccati_psd(const MatrixXd& H, MatrixXd& X) {
  const int n = static_cast<int>(H.rows() / 2);
  MatrixXd Z;
  if (!matrix_sign(H, Z)) return false;
  // range(I − Z) is the stable subspace (sign = −1 there)
  const MatrixXd P = MatrixXd::Identity(2 * n, 2 * n) - Z;
  const Eigen::ColPivHouseholderQR<MatrixXd> qr(P);
  if (qr.rank() != n) return false;
  const MatrixXd basis = (qr.householderQ() * MatrixXd::Identity(2 * n, n));
  const MatrixXd X1 = basis.topRows(n), X2 = basis.bottomRows(n);
  const Eigen::FullPivLU<MatrixXd> lu1(X1);
  if (!lu1.isInvertible()) return false;
  X = X2 * lu1.inverse();
  X = 0.5 * (X + X.transpose());
  return Eigen::SelfAdjointEigenSolver<MatrixXd>(X).eigenvalues().minCoeff() > -1e-9 * std::max(1.0, X.norm());
}

bool dgkf_feasible(const GeneralisedPlant& P, double g) {
  const int n = P.n();
  MatrixXd HX(2 * n, 2 * n), HY(2 * n, 2 * n);
  HX << P.A, P.B1 * P.B1.transpose() / (g * g) - P.B2 * P.B2.transpose(), -P.C1.transpose() * P.C1, -P.A.transpose();
  HY << P.A.transpose(), P.C1.transpose() * P.C1 / (g * g) - P.C2.transpose() * P.C2, -P.B1 * P.B1.transpose(), -P.A;
  MatrixXd X, Y;
  if (!riccati_psd(HX, X) || !riccati_psd(HY, Y)) return false;
  const Eigen::VectorXcd ev = (X * Y).eigenvalues();
  return ev.cwiseAbs().maxCoeff() < g * g;
}

double dgkf_gamma(const GeneralisedPlant& P) {
  double lo = 1e-6, hi = 1.0;
  while (!dgkf_feasible(P, hi)) hi *= 2;
  while (hi / lo > 1 + 1e-10) {
    const double mid = std::sqrt(lo * hi);
    (dgkf_feasible(P, mid) ? hi : lo) = mid;
  }
  return hi;
}

// A plant in DGKF's normalised form: w = [d; v], z = [C1a x; u], y = C2 x + v.
GeneralisedPlant normalised_plant(const MatrixXd& A, const MatrixXd& B1a, const MatrixXd& B2, const MatrixXd& C1a,
                                  const MatrixXd& C2) {
  const int n = static_cast<int>(A.rows()), nd = static_cast<int>(B1a.cols()), nu = static_cast<int>(B2.cols());
  const int ny = static_cast<int>(C2.rows()), nza = static_cast<int>(C1a.rows());
  GeneralisedPlant P;
  P.time = TimeDomain::Continuous;
  P.A = A;
  P.B1 = MatrixXd::Zero(n, nd + ny);
  P.B1.leftCols(nd) = B1a;
  P.B2 = B2;
  P.C1 = MatrixXd::Zero(nza + nu, n);
  P.C1.topRows(nza) = C1a;
  P.D12 = MatrixXd::Zero(nza + nu, nu);
  P.D12.bottomRows(nu).setIdentity();
  P.C2 = C2;
  P.D21 = MatrixXd::Zero(ny, nd + ny);
  P.D21.rightCols(ny).setIdentity();
  P.D11 = MatrixXd::Zero(nza + nu, nd + ny);
  return P;
}

// Force disturbance, position measured with noise, z = [position; u]
// (tests/data/controllers/double-integrator.yaml).
GeneralisedPlant force_double_integrator() {
  MatrixXd A(2, 2), B1a(2, 1), B2(2, 1), C1a(1, 2), C2(1, 2);
  A << 0, 1, 0, 0;
  B1a << 0, 1;
  B2 << 0, 1;
  C1a << 1, 0;
  C2 << 1, 0;
  return normalised_plant(A, B1a, B2, C1a, C2);
}

// Certified, and γ as tight as the certificate proves (docs/maths.md (152b)): the closed
// loop's norm, recomputed here from the controller alone, is γ to the norm's tolerance.
void expect_certified(const GeneralisedPlant& P, const hinf::synth::ControllerSynthesisResult& r) {
  const hinf::StateSpace cl = hinf::closed_loop(P, r.controller);
  const double norm = P.time == TimeDomain::Discrete ? hinf::certify::discrete_hinf_norm(cl).norm
                                                     : hinf::certify::continuous_hinf_norm(cl).norm;
  EXPECT_LE(norm, r.gamma * (1 + 1e-6));
  EXPECT_GE(norm, r.gamma * (1 - 1e-6)) << "gamma above the controller's certified norm";
  EXPECT_TRUE(r.certificate.passed);
}

TEST(ControllerSynthesis, DoubleIntegratorMatchesDgkf) {
  const GeneralisedPlant P = force_double_integrator();
  const double reference = dgkf_gamma(P);
  for (bool strictly_proper : {true, false}) {
    const auto r = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {strictly_proper, std::nullopt, std::nullopt});
    EXPECT_NEAR(r.gamma / reference, 1.0, 1e-6) << "strictly proper " << strictly_proper;
    expect_certified(P, r);
  }
}

// The Chilali–Gahinet disk (docs/maths.md (153)): every closed-loop pole, recomputed from
// the controller, inside |λ| < r; γ no better than the unconstrained optimum; and the
// γ-optimal controller's ill-conditioning (a pole near −1e8 rad/s, cond(N) ~ 5e4) gone.
TEST(ControllerSynthesis, PoleDiskConfinesTheClosedLoop) {
  const GeneralisedPlant P = force_double_integrator();
  const auto free = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {true, std::nullopt, std::nullopt});
  for (double r : {2.0, 5.0}) {
    const auto disk = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {true, r, std::nullopt});
    const Eigen::VectorXcd poles = hinf::closed_loop(P, disk.controller).A.eigenvalues();
    EXPECT_LT(poles.cwiseAbs().maxCoeff(), r) << "r = " << r;
    EXPECT_GE(disk.gamma, dgkf_gamma(P) * (1 - 1e-9)) << "r = " << r;
    EXPECT_LT(disk.certificate.cond_N, free.certificate.cond_N / 100) << "r = " << r;
    ASSERT_TRUE(disk.gamma_without_disk.has_value());  // the unconstrained γ*, reported beside
    EXPECT_NEAR(*disk.gamma_without_disk / dgkf_gamma(P), 1.0, 1e-6) << "r = " << r;
    expect_certified(P, disk);
  }
  EXPECT_GT(free.certificate.max_pole_modulus, 1e6);  // what the disk cures
}

TEST(ControllerSynthesis, RandomPlantsMatchDgkf) {
  std::mt19937 g(7);
  for (int trial = 0; trial < 4; ++trial) {
    const int n = 3 + trial % 2;
    const MatrixXd A = hinf::test::random_matrix(g, n, n);  // unstable in general
    const GeneralisedPlant P = normalised_plant(A, hinf::test::random_matrix(g, n, 2), hinf::test::random_matrix(g, n, 1),
                                                hinf::test::random_matrix(g, 2, n), hinf::test::random_matrix(g, 1, n));
    const double reference = dgkf_gamma(P);
    const auto r = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {false, std::nullopt, std::nullopt});
    EXPECT_NEAR(r.gamma / reference, 1.0, 1e-6) << "trial " << trial;
    expect_certified(P, r);
  }
}

// The range n = 2 … 8, two controls and two measurements (random A: unstable in
// general), each γ against the DGKF γ-iteration.
TEST(ControllerSynthesis, RandomPlantsTwoToEightStatesMatchDgkf) {
  std::mt19937 g(11);
  for (int n = 2; n <= 8; ++n) {
    const MatrixXd A = hinf::test::random_matrix(g, n, n);
    const GeneralisedPlant P = normalised_plant(A, hinf::test::random_matrix(g, n, 2), hinf::test::random_matrix(g, n, 2),
                                                hinf::test::random_matrix(g, 2, n), hinf::test::random_matrix(g, 2, n));
    const double reference = dgkf_gamma(P);
    const auto r = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {false, std::nullopt, std::nullopt});
    EXPECT_NEAR(r.gamma / reference, 1.0, 1e-6) << "n = " << n << ", reference " << reference;
    expect_certified(P, r);
  }
}

// Seed 004's design model (tests/data/controllers/tumbling-hold-design.yaml): badly scaled
// (B2 = I/500, s_d = 1e-4, γ ≈ 0.06), solved only through the equilibration (154). Its
// DGKF normalisation: u' = W_u u, y' = y / s_v (γ unchanged).
TEST(ControllerSynthesis, TumblingHoldDesignMatchesDgkf) {
  const auto cfg = hinf::synth::parse_controller_config(
      hinf::synth::read_config_bytes(std::string(HINF_SOURCE_DIR) + "/tests/data/controllers/tumbling-hold-design.yaml"),
      "tumbling-hold-design.yaml");
  GeneralisedPlant N = cfg.plant;
  N.B2 /= 0.8;
  N.D12 /= 0.8;
  N.C2 /= 0.01;
  N.D21 /= 0.01;
  ASSERT_TRUE((N.D12.transpose() * N.D12).isIdentity(1e-15));
  ASSERT_TRUE((N.D21 * N.D21.transpose()).isIdentity(1e-15));
  const double reference = dgkf_gamma(N);
  const auto r = hinf::synth::synthesize_controller(cfg.plant, hinf::synth::Settings(), cfg.design);
  EXPECT_NEAR(r.gamma / reference, 1.0, 1e-6);
  expect_certified(cfg.plant, r);
}

// The physical model `model: tumbling_hold` (configs/tumbling-hold.yaml without its disk) is
// the hand-written design plant of tests/data/controllers/tumbling-hold-design.yaml.
TEST(ControllerSynthesis, TumblingHoldModelIsTheHandWrittenPlant) {
  const auto read = [](const std::string& path) {
    return hinf::synth::parse_controller_config(hinf::synth::read_config_bytes(std::string(HINF_SOURCE_DIR) + path), path);
  };
  const auto model = read("/configs/tumbling-hold.yaml");
  const auto hand = read("/tests/data/controllers/tumbling-hold-design.yaml");
  for (const auto& [a, b] : {std::pair{&model.plant.A, &hand.plant.A}, {&model.plant.B1, &hand.plant.B1},
                             {&model.plant.B2, &hand.plant.B2}, {&model.plant.C1, &hand.plant.C1},
                             {&model.plant.C2, &hand.plant.C2}, {&model.plant.D12, &hand.plant.D12},
                             {&model.plant.D21, &hand.plant.D21}}) {
    ASSERT_EQ(a->rows(), b->rows());
    ASSERT_EQ(a->cols(), b->cols());
    EXPECT_LE((*a - *b).cwiseAbs().maxCoeff(), 1e-18);
  }
  ASSERT_TRUE(model.design.pole_disk_radius.has_value());
  EXPECT_EQ(*model.design.pole_disk_radius, 2.0);
  ASSERT_TRUE(model.design.robust.has_value());
}

// The γ back-off (docs/maths.md (149a)) on seed 004's plant: γ = (1 + b) γ* with γ* the DGKF
// optimum, certified, and the recovery well conditioned (the γ-optimal one: cond(N) 7.5e4, a
// pole near −1.8e5 rad/s).
TEST(ControllerSynthesis, GammaBackoffConditionsTheController) {
  auto cfg = hinf::synth::parse_controller_config(
      hinf::synth::read_config_bytes(std::string(HINF_SOURCE_DIR) + "/tests/data/controllers/tumbling-hold-design.yaml"),
      "tumbling-hold-design.yaml");
  GeneralisedPlant N = cfg.plant;  // the DGKF normalisation, as above
  N.B2 /= 0.8;
  N.D12 /= 0.8;
  N.C2 /= 0.01;
  N.D21 /= 0.01;
  const double reference = dgkf_gamma(N);
  const auto optimal = hinf::synth::synthesize_controller(cfg.plant, cfg.settings, cfg.design);
  EXPECT_GT(optimal.certificate.cond_N, 1e4);
  cfg.settings.gamma_backoff = 0.05;
  const auto r = hinf::synth::synthesize_controller(cfg.plant, cfg.settings, cfg.design);
  ASSERT_TRUE(r.gamma_optimal.has_value());
  EXPECT_NEAR(*r.gamma_optimal / reference, 1.0, 1e-6);
  // recovered at 1.05 γ*; what is written is the controller's certified norm, between the
  // optimum and that level (docs/maths.md (152b))
  EXPECT_LE(r.gamma, 1.05 * reference * (1 + 1e-6));
  EXPECT_GE(r.gamma, reference * (1 - 1e-6));
  EXPECT_FALSE(r.stopped_short.has_value());
  EXPECT_LT(r.certificate.cond_N, 100.0);
  EXPECT_LT(r.certificate.max_pole_modulus, 10.0);
  expect_certified(cfg.plant, r);
}

// An optimum approached only in the limit (tests/data/controllers/optimum-in-the-limit.yaml: w is
// measurement noise only, and T(1) = 1 for every stabilising controller, so γ* = 1): the
// solver's end game fails on round-off; the last centred point is kept, recovered and
// certified, and the result says the solver stopped short (docs/maths.md §5.10). Once exit 4.
TEST(ControllerSynthesis, AnOptimumReachedOnlyInTheLimitKeepsTheLastCentredPoint) {
  const auto cfg = hinf::synth::parse_controller_config(
      hinf::synth::read_config_bytes(std::string(HINF_SOURCE_DIR) + "/tests/data/controllers/optimum-in-the-limit.yaml"),
      "optimum-in-the-limit.yaml");
  const auto r = hinf::synth::synthesize_controller(cfg.plant, cfg.settings, cfg.design);
  ASSERT_TRUE(r.stopped_short.has_value());
  // the report says what the gap is: here not bounded (the accurate Newton step failed at
  // the last centred point), never "relative gap inf"
  EXPECT_NE(r.stopped_short->find("returned the last centred point (its gap not bounded"), std::string::npos)
      << *r.stopped_short;
  EXPECT_EQ(r.stopped_short->find("inf"), std::string::npos) << *r.stopped_short;
  EXPECT_GE(r.gamma, 1.0);  // γ* = 1: no controller does better
  EXPECT_LT(r.gamma, 1.01);
  expect_certified(cfg.plant, r);
}

// A fast unstable pole seen through an integrator, P(s) = 1/(s (s − p)) in DGKF's normalised
// form (tests/data/controllers/badly-scaled-unstable.yaml at p = 1e5): γ* ≥ 2p², the least
// ‖K(1 − PK)⁻¹‖∞ of any stabilising controller on the noise-to-control channel alone
// (1/σ_H of P's antistable part (1/p)/(s − p), Glover 1986), and the γ-optimal point lies
// far out (γ* ≈ 2e10 for p = 1e5; 2.0e-4 above 2p² for p = 1e2 by Octave's hinfsyn). Once
// exit 4 from p = 1e4 (phase I's ball, 1e8, held no strictly feasible point; hinfsyn fails
// there too); now solved in a wider ball (docs/maths.md §4.3) and certified, γ within 2 % of
// the closed-form bound. For p = 1e2 the optimum lay on the default ball (20004.56, above
// hinfsyn's 20004.003): the wider ball's optimum is below hinfsyn's.
TEST(ControllerSynthesis, AFastUnstablePoleBehindAnIntegratorIsSolvedInAWiderBall) {
  for (const double p : {1e2, 1e3, 1e4, 1e5}) {
    GeneralisedPlant P = force_double_integrator();
    P.A(1, 1) = p;
    const auto r = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {true, std::nullopt, std::nullopt});
    const double bound = 2 * p * p;
    EXPECT_GE(r.gamma, bound) << "p = " << p;
    EXPECT_LE(r.gamma, 1.02 * bound) << "p = " << p;
    if (p == 1e2) {  // hinfsyn: 20004.00286 (its controller's norm, Octave's norm(·, inf))
      ASSERT_TRUE(r.gamma_optimal.has_value());
      EXPECT_LE(*r.gamma_optimal, 20004.00286);
      EXPECT_LE(r.gamma, 20004.00286 * (1 + 1e-6));  // issue 35: ≤ hinfsyn × (1 + 1e-6)
    }
    expect_certified(P, r);
  }
}

// tests/data/controllers/NAME, parsed, and the controller synthesised for it.
std::pair<hinf::synth::ControllerConfig, hinf::synth::ControllerSynthesisResult> synthesise_data_config(
    const std::string& name) {
  auto cfg = hinf::synth::parse_controller_config(
      hinf::synth::read_config_bytes(std::string(HINF_SOURCE_DIR) + "/tests/data/controllers/" + name), name);
  auto r = hinf::synth::synthesize_controller(cfg.plant, cfg.settings, cfg.design);
  return {std::move(cfg), std::move(r)};
}

// A singular problem (tests/data/controllers/singular-noise-free.yaml: y = x1 noise-free,
// D21 = 0, and u2 free, D12 = [0 1; 0 0]): the LMI's optimum is approached only as R and S
// grow, and in the optimum's ball (1e12) I − R S is singular to working precision at the
// optimum and at every back-off — exit 4 before issue 35's narrower balls. Now the LMI is
// solved again in a narrower ball and the controller recovered there (docs/maths.md §4.3):
// certified, γ within 1e-4 of the wider ball's optimum (measured: 6.6e-5 above it).
TEST(ControllerSynthesis, ASingularProblemIsRecoveredInANarrowerBall) {
  const auto [cfg, r] = synthesise_data_config("singular-noise-free.yaml");
  ASSERT_TRUE(r.narrower_ball.has_value());
  ASSERT_TRUE(r.gamma_optimal_wider_ball.has_value());
  EXPECT_LT(*r.narrower_ball, 1e8);
  EXPECT_LT(r.gamma, *r.gamma_optimal_wider_ball * (1 + 1e-4));
  expect_certified(cfg.plant, r);
}

// A singular problem whose optimum's ball certifies a controller only at a large back-off
// (tests/data/controllers/singular-large-backoff.yaml: closed loop 3.1 % above that ball's
// optimum): a narrower ball's controller, recovered within 1e-6 of its own optimum, has the
// smaller certified norm and is the one written (docs/maths.md §4.3; measured 0.31 % above
// the wider ball's optimum). Before, the wider ball's controller was written.
TEST(ControllerSynthesis, ALargeBackOffGivesWayToANarrowerBall) {
  const auto [cfg, r] = synthesise_data_config("singular-large-backoff.yaml");
  ASSERT_TRUE(r.narrower_ball.has_value());
  ASSERT_TRUE(r.wider_ball_certified_norm.has_value());
  ASSERT_TRUE(r.gamma_optimal_wider_ball.has_value());
  EXPECT_LT(r.gamma, *r.wider_ball_certified_norm);
  EXPECT_LT(r.gamma, *r.gamma_optimal_wider_ball * (1 + 1e-2));
  expect_certified(cfg.plant, r);
}

// γ* = 0 answered exactly (issue "No silently wrong answer", docs/maths.md (152b)): when z
// sees neither the state nor the control (C1 = 0, D12 = 0), or w reaches neither the state
// nor the measurement (B1 = 0, D21 = 0), every stabilising controller gives T_zw = D11.
// With D11 = 0 the written γ is 0 exactly; with D11 ≠ 0 it is σ_max(D11). The closed loop's
// stability and zero output matrix are recomputed here from the controller alone.
TEST(ControllerSynthesis, PerformanceChannelsOutOfReachAreAnsweredExactly) {
  for (const bool z_blind : {true, false}) {
    GeneralisedPlant P = force_double_integrator();
    if (z_blind) {
      P.C1.setZero();
      P.D12.setZero();
    } else {
      P.B1.setZero();
      P.D21.setZero();
    }
    const auto r = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {true, std::nullopt, std::nullopt});
    EXPECT_TRUE(r.certificate.passed) << "z blind " << z_blind;
    EXPECT_EQ(r.gamma, 0.0) << "z blind " << z_blind;
    const hinf::StateSpace cl = hinf::closed_loop(P, r.controller);
    EXPECT_LT(cl.A.eigenvalues().real().maxCoeff(), 0.0);
    EXPECT_EQ((z_blind ? cl.C : cl.B).norm(), 0.0);
    if (z_blind) {
      P.D11(0, 0) = 0.5;  // T_zw = D11 for every stabilising controller: γ* = 0.5
      const auto d = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {true, std::nullopt, std::nullopt});
      EXPECT_TRUE(d.certificate.passed);
      EXPECT_GE(d.gamma, 0.5);
      EXPECT_LE(d.gamma, 0.5 * (1 + 1e-9));
    }
  }
}

// Seed 004 with ten times its rate uncertainty (tests/data/controllers/robust-10x.yaml): the
// H∞-optimal controller fails the small-gain test, the robust design (160a) passes it. ‖T_qp‖∞
// recomputed here from the controller and the channel (H, E).
TEST(ControllerSynthesis, RobustDesignPassesSmallGainWhereTheOptimalControllerFails) {
  const auto cfg = hinf::synth::parse_controller_config(
      hinf::synth::read_config_bytes(std::string(HINF_SOURCE_DIR) + "/tests/data/controllers/robust-10x.yaml"),
      "robust-10x.yaml");
  const auto r = hinf::synth::synthesize_controller(cfg.plant, cfg.settings, cfg.design);
  ASSERT_TRUE(r.robust_synthesis);
  EXPECT_GE(*r.nominal_robust_channel_norm, 1.0);
  const hinf::StateSpace cl = hinf::closed_loop(cfg.plant, r.controller);
  const auto n = cfg.plant.n(), ncl = static_cast<int>(cl.A.rows());
  hinf::StateSpace t;
  t.A = cl.A;
  t.B = MatrixXd::Zero(ncl, cfg.design.robust->H.cols());
  t.B.topRows(n) = cfg.design.robust->H;
  t.C = MatrixXd::Zero(cfg.design.robust->E.rows(), ncl);
  t.C.leftCols(n) = cfg.design.robust->E;
  t.D = MatrixXd::Zero(t.C.rows(), t.B.cols());
  EXPECT_LT(hinf::certify::continuous_hinf_norm(t).norm, 1.0);
  EXPECT_GE(r.gamma, *r.gamma_without_disk);
  expect_certified(cfg.plant, r);
}

// ---------------------------------------------------------------- discrete: filtering
// The filter plant (docs/maths.md (1)–(3), no uncertainty) as a generalised plant whose
// controller is the filter: x(k+1) = A x + [B 0] w, z = L x − u, y = C x + [0 D] w.
GeneralisedPlant filtering_plant(const hinf::Plant& F) {
  GeneralisedPlant P;
  P.time = TimeDomain::Discrete;
  P.sample_time = 1;
  const int n = F.n(), p = F.p(), q = F.q();
  P.A = F.A;
  P.B1 = MatrixXd::Zero(n, p + q);
  P.B1.leftCols(p) = F.B;
  P.B2 = MatrixXd::Zero(n, F.l());
  P.C1 = F.L;
  P.D11 = MatrixXd::Zero(F.l(), p + q);
  P.D12 = -MatrixXd::Identity(F.l(), F.l());
  P.C2 = F.C;
  P.D21 = MatrixXd::Zero(F.m(), p + q);
  P.D21.rightCols(q) = F.D;
  return P;
}

TEST(ControllerSynthesis, DiscreteFilteringMatchesTheRiccatiFilters) {
  std::mt19937 g(11);
  for (int trial = 0; trial < 3; ++trial) {
    hinf::Plant F;
    const int n = 3;
    MatrixXd A = hinf::test::random_matrix(g, n, n);
    F.A = 0.8 * A / A.operatorNorm();  // Schur stable: the filter cannot move x
    F.B = hinf::test::random_matrix(g, n, 2);
    F.C = hinf::test::random_matrix(g, 1, n);
    F.D = hinf::test::random_matrix(g, 1, 1);
    F.L = hinf::test::random_matrix(g, 2, n);
    F.H.resize(n, 0);
    F.E.resize(0, n);
    F.G.resize(n, 0);
    const GeneralisedPlant P = filtering_plant(F);
    const double predicted = hinf::certify::optimal_hinf_predictor_gamma(F, 1e-10, hinf::Estimate::Predicted);
    const double filtered = hinf::certify::optimal_hinf_predictor_gamma(F, 1e-10, hinf::Estimate::Filtered);
    const auto strictly_proper = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {true, std::nullopt, std::nullopt});
    const auto proper = hinf::synth::synthesize_controller(P, hinf::synth::Settings(), {false, std::nullopt, std::nullopt});
    EXPECT_NEAR(strictly_proper.gamma / predicted, 1.0, 1e-6) << "trial " << trial;
    EXPECT_NEAR(proper.gamma / filtered, 1.0, 1e-6) << "trial " << trial;
    expect_certified(P, strictly_proper);
    expect_certified(P, proper);
  }
}

TEST(ControllerSynthesis, ContinuousNormByTheBilinearMapMatchesAFrequencyGrid) {
  std::mt19937 g(5);
  hinf::StateSpace G;
  const MatrixXd M = hinf::test::random_matrix(g, 4, 4);
  G.A = M - (M.eigenvalues().real().maxCoeff() + 0.3) * MatrixXd::Identity(4, 4);  // Hurwitz
  G.B = hinf::test::random_matrix(g, 4, 2);
  G.C = hinf::test::random_matrix(g, 3, 4);
  G.D = hinf::test::random_matrix(g, 3, 2);
  const hinf::certify::HinfNorm h = hinf::certify::continuous_hinf_norm(G);
  double grid = 0;
  for (int i = 0; i <= 4000; ++i) {
    const double w = std::pow(10.0, -3 + 6.0 * i / 4000);
    const Eigen::MatrixXcd resp = G.C.cast<std::complex<double>>() *
                                      (std::complex<double>(0, w) * Eigen::MatrixXcd::Identity(4, 4) - G.A.cast<std::complex<double>>())
                                          .inverse() *
                                      G.B.cast<std::complex<double>>() +
                                  G.D.cast<std::complex<double>>();
    grid = std::max(grid, Eigen::JacobiSVD<Eigen::MatrixXcd>(resp).singularValues()(0));
  }
  EXPECT_GE(h.norm, grid * (1 - 1e-12));
  EXPECT_LE(h.norm, grid * (1 + 1e-3));  // the grid misses the peak by little
}

// γ* = 0 exactly (tests/data/controllers/gamma-zero.yaml: w enters neither the state, z nor
// y): the file says gamma: 0, and verify and check read it back (they refused it, "gamma = 0:
// must be > 0", on this plant and on COMPleib's NN10).
TEST(ControllerSynthesis, AZeroGammaIsReadBack) {
  const std::string config = std::string(HINF_SOURCE_DIR) + "/tests/data/controllers/gamma-zero.yaml";
  const auto problem = hinf::synth::load_problem(config);
  const hinf::synth::SolveOutcome solved = problem->solve();
  EXPECT_EQ(solved.gamma, 0.0);
  const hinf::test::ScratchDir dir("gamma_zero");
  std::ofstream(dir / "k.yaml") << solved.file;
  EXPECT_TRUE(problem->verify(dir / "k.yaml").holds);
  const hinf::synth::CheckOutcome checked = problem->check(dir / "k.yaml", 1e-6);
  EXPECT_TRUE(checked.same) << checked.report;
}

}  // namespace
