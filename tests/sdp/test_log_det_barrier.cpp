// White-box tests of the generic LMI layer (synth/src/lmi) and the log-det barrier:
//  - M(x) of a toy LMI (symmetric / full / scalar variables, transposed and symmetrised
//    terms, constants) against a hand assembly written here from the term definitions;
//  - basis matrices Mᵢ against exact differences of evaluate() (M is affine);
//  - gradient tr(W Mᵢ) and Hessian tr(W Mᵢ W Mⱼ) against dense traces of the Mᵢ;
//  - Theorem 1's evaluate() against the dense docs/maths.md (18) assembly of certify/dense_lmi
//    (congruence diag(I, …, I, s·I) for the H/E balance s, λ = λ'/s²);
//  - Ipopt's second-order derivative checker on the barrier (phase I and phase II).
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ipopt_centering.hpp"
#include "log_det_barrier.hpp"
#include "hinf/sdp/path_following.hpp"
#include "hinf/certify/dense_lmi.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/models/plant.hpp"
#include "hinf/lmi/lmi_problem.hpp"
#include "random_plants.hpp"
#include "theorem1.hpp"
#include "hinf/synth/plant_scaling.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using hinf::lmi::LmiProblem;
using hinf::test::random_matrix;
using hinf::test::random_symmetric;
using hinf::test::random_vector;
using hinf::test::relative_error;
using hinf::test::random_plant_with_dimensions;
using hinf::Plant;

MatrixXd rnd_spd(std::mt19937& g, int n) {
  MatrixXd M = random_matrix(g, n, n);
  return M * M.transpose() + MatrixXd::Identity(n, n);
}

// Largest |entry| of A − B relative to max(1, ‖B‖_max).
// Dense checks shared by both LMIs: basis matrices vs differences of evaluate(),
// gradient/Hessian vs dense traces with the basis matrices, for a random SPD W.
void check_derivatives_dense(const LmiProblem& L, std::mt19937& g) {
  const int np = L.num_params(), N = L.order();
  const VectorXd x = random_vector(g, np);
  const MatrixXd Mx = L.evaluate(x);
  ASSERT_EQ(Mx.rows(), N);
  EXPECT_LT(relative_error(Mx, Mx.transpose()), 1e-15) << "M(x) not symmetric";
  MatrixXd sum = L.evaluate(VectorXd::Zero(np));
  EXPECT_LT(relative_error(sum, L.constant()), 1e-15);
  std::vector<MatrixXd> Mi(np);
  for (int i = 0; i < np; ++i) {
    Mi[i] = L.basis_matrix(i);
    // M affine: M(e_i) − M(0) = M_i exactly up to round-off
    VectorXd e = VectorXd::Zero(np);
    e(i) = 1.0;
    EXPECT_LT(relative_error(L.evaluate(e) - L.constant(), Mi[i]), 1e-14) << "basis matrix " << i;
    EXPECT_LT(relative_error(Mi[i], Mi[i].transpose()), 1e-15);
    EXPECT_GT(Mi[i].cwiseAbs().maxCoeff(), 0.0) << "parameter " << i << " does not enter M";
    sum += x(i) * Mi[i];
  }
  EXPECT_LT(relative_error(Mx, sum), 1e-12) << "M(x) != M0 + sum x_i M_i";

  // the sparse export lists the same matrices
  std::vector<MatrixXd> Ms(np, MatrixXd::Zero(N, N));
  for (const auto& e : L.sparse_entries()) {
    ASSERT_LE(e.row, e.col);
    Ms[e.param](e.row, e.col) += e.value;
    if (e.row != e.col) Ms[e.param](e.col, e.row) += e.value;
  }
  for (int i = 0; i < np; ++i) EXPECT_LT(relative_error(Ms[i], Mi[i]), 1e-14) << "sparse entries of M_" << i;

  const MatrixXd W = rnd_spd(g, N) / N;
  VectorXd gr;
  L.trace_products(W, gr);
  ASSERT_EQ(gr.size(), np);
  MatrixXd H;
  L.hessian(W, H);
  ASSERT_EQ(H.rows(), np);
  ASSERT_EQ(H.cols(), np);
  std::vector<MatrixXd> WM(np);
  for (int i = 0; i < np; ++i) WM[i] = W * Mi[i];
  double gmax = 0, hmax = 0;
  for (int i = 0; i < np; ++i) gmax = std::max(gmax, std::abs(WM[i].trace()));
  MatrixXd Href(np, np);
  for (int i = 0; i < np; ++i)
    for (int j = 0; j < np; ++j) {
      Href(i, j) = (WM[i] * WM[j]).trace();
      hmax = std::max(hmax, std::abs(Href(i, j)));
    }
  for (int i = 0; i < np; ++i)
    EXPECT_NEAR(gr(i), WM[i].trace(), 1e-12 * std::max(1.0, gmax)) << "gradient " << i;
  for (int i = 0; i < np; ++i)
    for (int j = 0; j < np; ++j)
      ASSERT_NEAR(H(i, j), Href(i, j), 1e-11 * std::max(1.0, hmax)) << "Hessian (" << i << "," << j << ")";
}

TEST(LmiLayer, ToyLmiGradientHessianMatchDenseTraces) {
  std::mt19937 g(12);
  LmiProblem L({3, 2, 4, 1});
  const auto X = L.add_symmetric("X", 3);
  const auto Y = L.add_full("Y", 2, 4);
  const auto z = L.add_scalar("z");
  L.add_term(0, 0, X, random_matrix(g, 3, 3), MatrixXd::Identity(3, 3), false, true);
  L.add_term(0, 0, X, -2.0 * MatrixXd::Identity(3, 3), MatrixXd::Identity(3, 3));  // α·I factors
  L.add_term(0, 2, Y, random_matrix(g, 3, 2), random_matrix(g, 4, 4));
  L.add_term(1, 2, Y, random_matrix(g, 2, 4), random_matrix(g, 2, 4), true);
  L.add_term(2, 2, Y, random_matrix(g, 4, 2), random_matrix(g, 4, 4), false, true);
  L.add_term(1, 3, X, random_matrix(g, 2, 3), random_matrix(g, 3, 1));
  L.add_scalar_term(1, 1, z, random_symmetric(g, 2));
  L.add_scalar_term(0, 3, z, random_matrix(g, 3, 1));
  L.add_scalar_term(3, 3, z, -MatrixXd::Identity(1, 1));
  L.add_constant(1, 1, -MatrixXd::Identity(2, 2));
  check_derivatives_dense(L, g);
}

// ---------------------------------------------------------------- Theorem 1
struct Dims {
  int n, p, m, q, l, j, k;
};
const Dims kDims[] = {{3, 2, 1, 2, 2, 1, 2}, {5, 1, 2, 3, 1, 2, 1}, {2, 3, 2, 2, 3, 0, 0},
                      {4, 2, 3, 1, 2, 0, 0}, {1, 1, 1, 1, 1, 1, 1}};

TEST(LmiLayer, Theorem1GradientHessianMatchDenseTraces) {
  std::mt19937 g(13);
  for (const Dims& d : kDims) {
    SCOPED_TRACE(testing::Message() << "n=" << d.n << " p=" << d.p << " m=" << d.m << " q=" << d.q
                                    << " l=" << d.l << " j=" << d.j << " k=" << d.k);
    const Plant P = random_plant_with_dimensions(g, d.n, d.p, d.m, d.q, d.l, d.j, d.k);
    const auto T = hinf::synth::build_theorem1(P);
    const int expected_vars = d.n * (d.n + 1) + d.n * d.n + d.n * d.m + d.l * d.n + 1 + (d.j > 0 ? 1 : 0);
    EXPECT_EQ(T.lmi.num_params(), expected_vars);
    EXPECT_EQ(T.lmi.order(), 4 * d.n + d.p + d.q + d.l + d.j);
    check_derivatives_dense(T.lmi, g);
  }
}

// Check 1 on graded matrices, like LMI docs/maths.md (18) when a config's H and E are far apart in
// scale: M = S·M̃·S, M̃ = −Q diag(1e-10 … 1) Qᵀ (Q random orthogonal, 8×8), S = diag(1, …,
// 1, 1e4, 1e4), so ‖M‖ ~ 1e8 while the eigenvalue nearest zero is ~ −1e-10, far below a
// symmetric eigensolver's absolute accuracy on M (~ε‖M‖; on seeds 1 and 4 it returns a
// positive value). Reference: −1/λ_max(M⁻¹) with M⁻¹ = −S⁻¹ Q diag(1/λ) Qᵀ S⁻¹ from the
// construction, in long double (M itself is rounded entrywise, which moves that
// eigenvalue by ~cond(M̃)·ε ≈ 1e-6 relative).
TEST(LmiLayer, DefinitenessCheckOnGradedMatrix) {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    std::mt19937 g(seed);
    std::normal_distribution<double> nd;
    const int n = 8;
    MatrixXd X(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) X(i, j) = nd(g);
    const MatrixXd Q = Eigen::HouseholderQR<MatrixXd>(X).householderQ();
    VectorXd lam(n);
    for (int i = 0; i < n; ++i) lam(i) = std::pow(10.0, -10.0 + 10.0 * i / (n - 1));
    VectorXd sc = VectorXd::Ones(n);
    sc(6) = sc(7) = 1e4;
    const MatrixXd Mt = -(Q * lam.asDiagonal() * Q.transpose());
    const MatrixXd M = sc.asDiagonal() * (0.5 * (Mt + Mt.transpose())) * sc.asDiagonal();
    using MatL = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> isc = sc.cast<long double>().cwiseInverse();
    const MatL Ninv = isc.asDiagonal() * Q.cast<long double>() *
                      lam.cast<long double>().cwiseInverse().asDiagonal() * Q.transpose().cast<long double>() *
                      isc.asDiagonal();
    const long double mu = Eigen::SelfAdjointEigenSolver<MatL>(Ninv, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
    const double ref = static_cast<double>(-1.0L / mu);
    const auto d = hinf::certify::check_negative_definite(M, 0.0);
    ASSERT_TRUE(d.negative_definite) << "seed " << seed << ": max_eig " << d.max_eig << ", reference " << ref;
    EXPECT_NEAR(d.max_eig, ref, 1e-4 * std::abs(ref)) << "seed " << seed;
    // the margin: M ≺ −μI iff μ < |λ_max|
    EXPECT_TRUE(hinf::certify::check_negative_definite(M, 0.5 * std::abs(ref)).negative_definite);
    EXPECT_FALSE(hinf::certify::check_negative_definite(M, 2.0 * std::abs(ref)).negative_definite);
  }
}

TEST(LmiLayer, Theorem1EvaluateMatchesDenseSpec20) {
  std::mt19937 g(14);
  for (const Dims& d : kDims) {
    SCOPED_TRACE(testing::Message() << "n=" << d.n << " j=" << d.j);
    const Plant P = random_plant_with_dimensions(g, d.n, d.p, d.m, d.q, d.l, d.j, d.k);
    const bool unc = d.j > 0;
    const hinf::synth::PlantScaling sc = hinf::synth::uncertainty_split(P);
    const double s = sc.uncertainty;
    if (unc) {  // the split brings ‖sH‖_F and ‖E/s‖_F within a factor 2 (docs/maths.md (24))
      const double ratio = (s * P.H).norm() / (P.E / s).norm();
      EXPECT_LE(ratio, 2.0);
      EXPECT_GE(ratio, 0.5);
      EXPECT_EQ(s, std::ldexp(1.0, std::ilogb(s))) << "a power of two";
    }
    const auto T = hinf::synth::build_theorem1(hinf::synth::scaled_plant(P, sc));
    for (int trial = 0; trial < 4; ++trial) {
      const VectorXd x = random_vector(g, T.lmi.num_params());
      hinf::certify::Theorem1Point pt;
      pt.R = T.lmi.value(T.R, x);
      pt.S = T.lmi.value(T.S, x);
      pt.AF_bar = T.lmi.value(T.AFbar, x);
      pt.BF_bar = T.lmi.value(T.BFbar, x);
      pt.CF_bar = T.lmi.value(T.CFbar, x);
      EXPECT_LT(relative_error(pt.R, pt.R.transpose()), 1e-15);
      pt.g = T.lmi.value(T.g, x)(0, 0);
      if (unc) pt.lambda = VectorXd::Constant(1, T.lmi.value(T.lambda[0], x)(0, 0) / (s * s));
      const MatrixXd Md = hinf::certify::theorem1_matrix(P, pt);
      const int N = T.lmi.order();
      ASSERT_EQ(Md.rows(), N);
      VectorXd dsc = VectorXd::Ones(N);
      if (unc) dsc.tail(d.j).setConstant(s);
      const MatrixXd expected = dsc.asDiagonal() * Md * dsc.asDiagonal();
      EXPECT_LT(relative_error(T.lmi.evaluate(x), expected), 1e-12) << "trial " << trial;
    }
  }
}

// ---------------------------------------------------------------- barrier vs finite differences
// Directional central differences of LogDetBarrier::value / gradient along random
// directions v at a point on the central path:  (f(z+εv) − f(z−εv))/2ε ≈ ∇fᵀv and
// (∇f(z+εv) − ∇f(z−εv))/2ε ≈ ∇²f v. Truncation error O(ε²), round-off O(u·|f|/ε).
void check_barrier_fd(hinf::sdp::LogDetBarrier& b, const VectorXd& z, std::mt19937& g,
                      double tol) {
  double f0 = 0;
  VectorXd g0;
  MatrixXd H0;
  ASSERT_TRUE(b.value(z, f0));
  ASSERT_TRUE(b.gradient(z, g0));
  ASSERT_TRUE(b.hessian(z, H0));
  EXPECT_LT(relative_error(H0, H0.transpose()), 1e-14);
  for (int trial = 0; trial < 5; ++trial) {
    VectorXd v = random_vector(g, static_cast<int>(z.size()));
    // unit length in the local (Hessian) norm, so ε is relative to the distance to the boundary
    v /= std::sqrt(v.dot(H0 * v));
    const double eps = 1e-4;
    double fp = 0, fm = 0;
    VectorXd gp, gm;
    ASSERT_TRUE(b.value(z + eps * v, fp));
    ASSERT_TRUE(b.value(z - eps * v, fm));
    ASSERT_TRUE(b.gradient(z + eps * v, gp));
    ASSERT_TRUE(b.gradient(z - eps * v, gm));
    const double dir = g0.dot(v), dir_fd = (fp - fm) / (2 * eps);
    const VectorXd Hv = H0 * v, Hv_fd = (gp - gm) / (2 * eps);
    // v has unit local norm, so vᵀHv = 1: errors are relative to the barrier's own scale
    EXPECT_NEAR(dir_fd, dir, tol * std::max(1.0, std::abs(dir))) << "trial " << trial;
    const double herr = (Hv_fd - Hv).norm() / Hv.norm();
    EXPECT_LT(herr, tol) << "trial " << trial;
    std::printf("  [fd] trial %d: |grad err| %.2e (|g.v| %.2e), rel Hessian err %.2e\n", trial,
                std::abs(dir_fd - dir), std::abs(dir), herr);
  }
}

// Phase II barrier on a well-conditioned toy LMI (M₀ = −I plus small variable terms) at a
// generic interior point (not centred, so the gradient is not small). At points on the
// central path of Theorem 1 the slack is ill-conditioned (cond ~ 1e10 and more), and
// differences of log det lose ~cond·u: finite differences are not decisive there (Ipopt's
// checker is run at such a point below).
TEST(LmiLayer, BarrierMatchesFiniteDifferencesPhase2) {
  std::mt19937 g(16);
  LmiProblem L({3, 2, 4});
  const auto X = L.add_symmetric("X", 3);
  const auto Y = L.add_full("Y", 2, 4);
  const auto z = L.add_scalar("z");
  L.add_term(0, 0, X, random_matrix(g, 3, 3), MatrixXd::Identity(3, 3), false, true);
  L.add_term(0, 2, Y, random_matrix(g, 3, 2), random_matrix(g, 4, 4));
  L.add_term(1, 2, Y, random_matrix(g, 2, 4), random_matrix(g, 2, 4), true);
  L.add_scalar_term(1, 1, z, random_symmetric(g, 2));
  L.add_scalar_term(2, 2, z, -MatrixXd::Identity(4, 4));
  for (int b = 0; b < 3; ++b) L.add_constant(b, b, -MatrixXd::Identity(L.block_size(b), L.block_size(b)));
  const VectorXd c = random_vector(g, L.num_params());
  hinf::sdp::LogDetBarrier b(L, c, 1e-9, 10.0, false);
  b.set_t(1.7);
  const VectorXd x = 0.05 * random_vector(g, L.num_params());
  ASSERT_TRUE(b.inside(x));
  check_barrier_fd(b, x, g, 1e-6);
  // W = slack⁻¹ is symmetrised exactly (an in-place W = (W + Wᵀ)/2 through Eigen aliases
  // and leaves W asymmetric at round-off level, which moved the solver's path)
  VectorXd gx;
  ASSERT_TRUE(b.gradient(x, gx));
  EXPECT_EQ((b.W() - b.W().transpose()).cwiseAbs().maxCoeff(), 0.0);
}

// The scaled Jacobian of the QR Newton step: GᵀG is the barrier Hessian tr(W Mᵢ W Mⱼ)
// for W = TᵀT, and with first_row f the emitted rows plus the explicit Hessian of the
// remaining rows of T, W_m = T[0:f]ᵀ T[0:f], make up the same matrix (the split that
// LogDetBarrier::accurate_newton uses).
TEST(LmiLayer, ScaledJacobianGramIsTheHessian) {
  std::mt19937 g(23);
  const Plant P = random_plant_with_dimensions(g, 3, 2, 1, 2, 2, 1, 2);
  const auto T1 = hinf::synth::build_theorem1(P);
  const LmiProblem& L = T1.lmi;
  const int N = L.order(), np = L.num_params();
  const MatrixXd T = random_matrix(g, N, N);
  MatrixXd H;
  L.hessian(T.transpose() * T, H);
  MatrixXd G(N * (N + 1) / 2, np);
  L.scaled_jacobian(T, G);
  EXPECT_LT(relative_error(G.transpose() * G, H), 1e-12);
  for (int f : {1, N / 2, N - 1}) {
    MatrixXd Gf(LmiProblem::scaled_jacobian_rows(N, f), np), Hm;
    L.scaled_jacobian(T, Gf, f);
    L.hessian(T.topRows(f).transpose() * T.topRows(f), Hm);
    EXPECT_LT(relative_error(Gf.transpose() * Gf + Hm, H), 1e-12) << "f = " << f;
  }
}

// Where the explicit Hessian is well conditioned, the QR Newton step, its decrement and
// the QR path tangent equal the explicit ones (independent: LDLᵀ of the assembled H).
TEST(LmiLayer, QrNewtonStepMatchesExplicitWhereWellConditioned) {
  std::mt19937 g(29);
  const Plant P = random_plant_with_dimensions(g, 3, 2, 1, 2, 2, 1, 2);
  const auto T = hinf::synth::build_theorem1(P);
  const VectorXd c = T.lmi.cost_of(T.g);
  hinf::sdp::Options st;
  st.relative_gap_tol = 10.0;  // first phase-II centring: a well-conditioned point
  const auto sol = hinf::sdp::minimize_linear(T.lmi, c, st);
  hinf::sdp::LogDetBarrier b(T.lmi, c, st.lmi_margin, st.feasibility_radius, false);
  b.set_t(3.0);
  const VectorXd x = sol.x;
  ASSERT_TRUE(b.inside(x));
  VectorXd grad, dz_qr, tan_qr, tan_ex;
  MatrixXd H;
  double l2_qr = 0, l2_ex = 0;
  ASSERT_TRUE(b.gradient(x, grad) && b.hessian(x, H));
  ASSERT_TRUE(b.accurate_newton(x, dz_qr, l2_qr));
  ASSERT_TRUE(b.newton_decrement2(x, l2_ex));
  const VectorXd dz_ex = -H.ldlt().solve(grad);
  EXPECT_LT((dz_qr - dz_ex).norm(), 1e-9 * dz_ex.norm());
  EXPECT_NEAR(l2_qr, l2_ex, 1e-9 * l2_ex);
  EXPECT_NEAR(l2_qr, -grad.dot(dz_ex), 1e-9 * l2_ex);
  ASSERT_TRUE(b.accurate_path_tangent(x, tan_qr) && b.path_tangent(x, tan_ex));
  EXPECT_LT((tan_qr - tan_ex).norm(), 1e-9 * tan_ex.norm());
}

// A phase-I point (x, s) of T: x = 0.3·N(0, 1) entries, s = max(0, λ_max(M(x))) + room, so
// that −M(x) − εI + sI ≻ 0 with margin `room` (less ε).
VectorXd phase1_point(const hinf::synth::Theorem1Lmi& T, std::mt19937& g, double room) {
  const int np = T.lmi.num_params();
  VectorXd z(np + 1);
  z.head(np) = 0.3 * random_vector(g, np);
  const double lmax = T.lmi.evaluate(z.head(np)).selfadjointView<Eigen::Lower>().eigenvalues().maxCoeff();
  z(np) = std::max(0.0, lmax) + room;
  return z;
}

TEST(LmiLayer, BarrierMatchesFiniteDifferencesPhase1) {
  std::mt19937 g(17);
  const Plant P = random_plant_with_dimensions(g, 4, 1, 2, 2, 3, 2, 1);
  const auto T = hinf::synth::build_theorem1(P);
  hinf::sdp::LogDetBarrier b(T.lmi, T.lmi.cost_of(T.g), 1e-9, 1e8, /*phase1=*/true);
  b.set_t(2.0);
  const VectorXd z = phase1_point(T, g, 0.5);
  check_barrier_fd(b, z, g, 1e-6);
}

// ---------------------------------------------------------------- Ipopt derivative test
// Runs Ipopt's second-order derivative checker on the barrier at z, returns its output.
std::string run_derivative_checker(hinf::sdp::LogDetBarrier& b, const VectorXd& z) {
  hinf::sdp::IpoptCentering ip;
  hinf::sdp::CenteringOptions opt;
  opt.derivative_test = true;
  opt.max_iterations = 1;
  std::fflush(stdout);
  testing::internal::CaptureStdout();
  (void)ip.run(b, z, opt);
  std::fflush(stdout);
  return testing::internal::GetCapturedStdout();
}

void expect_checker_clean(const std::string& out) {
  EXPECT_NE(out.find("Starting derivative checker"), std::string::npos) << out.substr(0, 2000);
  EXPECT_NE(out.find("No errors detected by derivative checker"), std::string::npos)
      << out.substr(0, 4000);
  EXPECT_EQ(out.find("Derivative checker detected"), std::string::npos) << out.substr(0, 4000);
}


TEST(LmiLayer, IpoptDerivativeCheckerPhase1) {
  std::mt19937 g(15);
  const Plant P = random_plant_with_dimensions(g, 3, 2, 1, 2, 2, 1, 2);
  const auto T = hinf::synth::build_theorem1(P);
  hinf::sdp::LogDetBarrier b(T.lmi, T.lmi.cost_of(T.g), 1e-9, 1e8, /*phase1=*/true);
  // small t: Ipopt's forward differences (step 1e-7) lose u·|f|/1e-7 to round-off,
  // so |f| = |t·s − log det …| must stay small next to its tolerance 1e-5
  b.set_t(1e-3);
  // Strictly inside (−M − εI + sI ≻ 0) with room to spare: Ipopt's derivative checker
  // evaluates at a random perturbation of z (option point_perturbation_radius, default 10),
  // which the centring adapter does not switch off.
  const VectorXd z = phase1_point(T, g, 1e4);
  ASSERT_TRUE(b.inside(z));
  expect_checker_clean(run_derivative_checker(b, z));
}

// Phase II barrier at a strictly feasible point of a small random plant, early on the
// central path (loose gap), where the slack is well conditioned: deep on the path of
// the paper's LMI the slack's condition number reaches 1e10 and Ipopt's forward
// differences (step 1e-7) are not decisive (the exact-trace tests above cover that).
// IpoptCentering sets point_perturbation_radius = 0 for the checker, so the reference
// point stays inside the LMI cone.
TEST(LmiLayer, IpoptDerivativeCheckerPhase2) {
  std::mt19937 g(15);
  const Plant P = random_plant_with_dimensions(g, 3, 2, 1, 2, 2, 1, 2);
  const auto T = hinf::synth::build_theorem1(P);
  const int np = T.lmi.num_params();
  const VectorXd c = T.lmi.cost_of(T.g);
  hinf::sdp::Options st;
  st.relative_gap_tol = 10.0;  // stop at the first phase-II centring: well inside the cone
  const auto sol = hinf::sdp::minimize_linear(T.lmi, c, st);
  ASSERT_EQ(sol.x.size(), np);
  hinf::sdp::LogDetBarrier b(T.lmi, c, st.lmi_margin, st.feasibility_radius, false);
  b.set_t(1e-3);
  ASSERT_TRUE(b.inside(sol.x)) << "solver returned a point outside the LMI";
  expect_checker_clean(run_derivative_checker(b, sol.x));
}

}  // namespace

// Progress of a solve (path_following.hpp): while a Newton iteration's Hessian is assembled
// the observer hears `assembling` reports (once per LMI term, so that a problem whose one
// iteration takes minutes still shows life), in both phases, with time that never goes
// back; the Newton-step and centring reports still come, and the solution is the same as
// without an observer.
TEST(PathFollowing, ObserverHearsTheHessianAssembly) {
  std::mt19937 g(31);
  const Plant P = random_plant_with_dimensions(g, 3, 2, 1, 2, 2, 1, 2);
  const auto T = hinf::synth::build_theorem1(P);
  const VectorXd c = T.lmi.cost_of(T.g);
  int assembling[3] = {0, 0, 0}, newton_steps = 0, centrings = 0;
  double last_time = 0;
  bool monotone = true;
  const auto sol = hinf::sdp::minimize_linear(T.lmi, c, hinf::sdp::Options{}, VectorXd(),
                                              [&](const hinf::sdp::Progress& p) {
                                                if (p.assembling) ++assembling[p.phase];
                                                else if (p.newton_step) ++newton_steps;
                                                else ++centrings;
                                                monotone = monotone && p.elapsed_s >= last_time;
                                                last_time = p.elapsed_s;
                                              });
  const auto quiet = hinf::sdp::minimize_linear(T.lmi, c, hinf::sdp::Options{});
  ASSERT_EQ(sol.status, hinf::sdp::Status::Solved);
  EXPECT_GT(assembling[1], 0);
  EXPECT_GT(assembling[2], 0);
  EXPECT_GT(newton_steps, 0);
  EXPECT_GT(centrings, 0);
  EXPECT_TRUE(monotone);
  EXPECT_EQ(sol.objective, quiet.objective);  // observing changes nothing
}

// The first centring of a phase starts far from its centre (here phase I from a start
// 10³ times larger than the problem's scale) and may need more Newton steps than a later
// one: it gets kFirstCentringBudgetFactor (4) times max_newton_per_centering
// (path_following.cpp; docs/maths.md §5.7). With a budget that every later centring fits
// and the first does not, the solve still succeeds, its first centring longer than the
// budget, no other one.
TEST(PathFollowing, TheFirstCentringOfAPhaseGetsALargerBudget) {
  std::mt19937 g(37);
  const Plant P = random_plant_with_dimensions(g, 3, 2, 1, 2, 2, 1, 2);
  const auto T = hinf::synth::build_theorem1(P);
  const VectorXd c = T.lmi.cost_of(T.g);
  const VectorXd x0 = 1e3 * random_vector(g, T.lmi.num_params());
  std::vector<std::pair<int, int>> newton;  // (phase, Newton steps) of every centring
  const auto record = [&](const hinf::sdp::Progress& p) {
    if (!p.assembling && !p.newton_step) newton.emplace_back(p.phase, p.newton);
  };
  hinf::sdp::Options short_budget;
  short_budget.max_newton_per_centering = 20;
  const auto sol = hinf::sdp::minimize_linear(T.lmi, c, short_budget, x0, record);
  ASSERT_EQ(sol.status, hinf::sdp::Status::Solved) << sol.detail;
  ASSERT_GE(newton.size(), 3u);
  EXPECT_GT(newton[0].second, short_budget.max_newton_per_centering);  // phase I's first: 42 steps
  EXPECT_LE(newton[0].second, 4 * short_budget.max_newton_per_centering);
  for (size_t k = 1; k < newton.size(); ++k)
    EXPECT_LE(newton[k].second, short_budget.max_newton_per_centering) << "centring " << k;
  // the same path as with the default budget, which the first centring fits
  const auto wide = hinf::sdp::minimize_linear(T.lmi, c, hinf::sdp::Options{}, x0);
  EXPECT_EQ(sol.objective, wide.objective);
}
