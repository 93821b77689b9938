// The verified optimality bracket (sdp/dual_bound.hpp, docs/maths.md §5.9) on problems whose
// optimum is known in closed form, and its refusals: a bound is written only when it is
// a theorem.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "hinf/lmi/lmi_problem.hpp"
#include "hinf/sdp/dual_bound.hpp"
#include "hinf/sdp/path_following.hpp"
#include "random_plants.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using hinf::lmi::LmiProblem;

// minimise g subject to [−g·I_p, Bᵀ; B, −I_m] ≺ 0, i.e. g > ‖B‖₂²: p* = σ_max(B)² (Schur
// complement), for a random B — with a symmetric X, −I ≺ X ≺ I (blocks 3 and 4), that does
// not enter the cost: the dual must price it at zero (Z₃ = Z₄) and can, strictly.
struct SchurProblem {
  LmiProblem lmi{std::vector<int>{}};
  hinf::lmi::VarId g, X;
  double optimum = 0;
};

SchurProblem schur_problem(unsigned seed, int p, int m, double scale) {
  std::mt19937 gen(seed);
  const MatrixXd B = scale * hinf::test::random_matrix(gen, m, p);
  SchurProblem s;
  s.lmi = LmiProblem({p, m, 2, 2});
  s.g = s.lmi.add_scalar("g");
  s.X = s.lmi.add_symmetric("X", 2);
  s.lmi.add_scalar_term(0, 0, s.g, -MatrixXd::Identity(p, p));
  s.lmi.add_constant(0, 1, B.transpose());
  s.lmi.add_constant(1, 1, -MatrixXd::Identity(m, m));
  s.lmi.add_term(2, 2, s.X, MatrixXd::Identity(2, 2), MatrixXd::Identity(2, 2));
  s.lmi.add_constant(2, 2, -MatrixXd::Identity(2, 2));
  s.lmi.add_term(3, 3, s.X, -MatrixXd::Identity(2, 2), MatrixXd::Identity(2, 2));
  s.lmi.add_constant(3, 3, -MatrixXd::Identity(2, 2));
  const double smax = Eigen::JacobiSVD<MatrixXd>(B).singularValues()(0);
  s.optimum = smax * smax;
  return s;
}

TEST(DualBound, BracketsTheClosedFormOptimum) {
  for (unsigned seed : {1u, 2u, 3u}) {
    for (double scale : {0.1, 1.0, 10.0}) {
      SCOPED_TRACE(testing::Message() << "seed " << seed << " scale " << scale);
      const SchurProblem s = schur_problem(seed, 3, 2, scale);
      const VectorXd c = s.lmi.cost_of(s.g);
      hinf::sdp::Options o;
      const hinf::sdp::Solution sol = hinf::sdp::minimize_linear(s.lmi, c, o);
      ASSERT_EQ(sol.status, hinf::sdp::Status::Solved);
      const hinf::sdp::DualBound b = hinf::sdp::verified_bracket(s.lmi, c, sol.x, o.lmi_margin);
      ASSERT_TRUE(b.verified) << b.detail;
      ASSERT_TRUE(b.upper_verified);
      EXPECT_LE(b.lower_bound, s.optimum) << "a lower bound above the optimum is false";
      EXPECT_GE(b.upper_bound, s.optimum);
      EXPECT_GT(b.lower_bound, s.optimum * (1 - 1e-6))
          << "the bracket should be tight: " << b.lower_bound << " " << s.optimum << " " << b.upper_bound << " dual "
          << b.dual_objective << " corr " << b.correction_bound << " res " << b.residual_bound;
    }
  }
}

// At a point that is not strictly feasible nothing is certified.
TEST(DualBound, RefusesAnInfeasiblePoint) {
  const SchurProblem s = schur_problem(4, 3, 2, 1.0);
  const VectorXd c = s.lmi.cost_of(s.g);
  VectorXd x = VectorXd::Zero(s.lmi.num_params());
  x(s.lmi.variable(s.g).offset) = 0.5 * s.optimum;  // g below p*: M(x) has a positive eigenvalue
  const hinf::sdp::DualBound b = hinf::sdp::verified_bracket(s.lmi, c, x, 0.0);
  EXPECT_FALSE(b.upper_verified);
  EXPECT_FALSE(b.verified);
  EXPECT_FALSE(b.detail.empty());
  EXPECT_TRUE(std::isinf(b.lower_bound));
}

// A dual point built far from the central path (the first phase-II centring, relative gap
// ~1) still gives a valid, if loose, bound — or none; never one above the optimum.
TEST(DualBound, LooseButValidFarFromTheOptimum) {
  const SchurProblem s = schur_problem(5, 4, 3, 1.0);
  const VectorXd c = s.lmi.cost_of(s.g);
  hinf::sdp::Options o;
  o.relative_gap_tol = 1e-2;
  const hinf::sdp::Solution sol = hinf::sdp::minimize_linear(s.lmi, c, o);
  ASSERT_EQ(sol.status, hinf::sdp::Status::Solved);
  const hinf::sdp::DualBound b = hinf::sdp::verified_bracket(s.lmi, c, sol.x, o.lmi_margin);
  if (b.verified) {
    EXPECT_LE(b.lower_bound, s.optimum);
  }
  EXPECT_TRUE(b.upper_verified);
}

// The data error of the stored LMI (basis_error) widens the bracket and is accounted for.
TEST(DualBound, DataErrorWidensTheBracket) {
  const SchurProblem s = schur_problem(6, 3, 2, 1.0);
  const VectorXd c = s.lmi.cost_of(s.g);
  const hinf::sdp::Solution sol = hinf::sdp::minimize_linear(s.lmi, c, hinf::sdp::Options());
  const hinf::sdp::DualBound exact = hinf::sdp::verified_bracket(s.lmi, c, sol.x, 1e-9);
  // an uncertainty of 1e-12 on every entry of the cost's Mᵢ (the −I of g in block 0)
  std::vector<hinf::lmi::SparseEntry> err;
  for (int i = 0; i < 3; ++i) err.push_back({s.lmi.variable(s.g).offset, i, i, 1e-12});
  const hinf::sdp::DualBound widened = hinf::sdp::verified_bracket(s.lmi, c, sol.x, 1e-9, err);
  ASSERT_TRUE(exact.verified) << exact.detail;
  ASSERT_TRUE(widened.verified) << widened.detail;
  EXPECT_LT(widened.lower_bound, exact.lower_bound);
  EXPECT_GT(widened.residual_bound, exact.residual_bound);
}

// x·I₂ + I₂ ≺ 0 and 1 − x ≺ 0 (x < −1 and x > 1) beside a feasible part −I ≺ X ≺ I:
// infeasible, and phase I's s* = inf max(x + 1, 1 − x, λ_max(±X) − 1) = 1 (at x = 0, X = 0).
TEST(DualBound, CertifiesInfeasibilityWithTheClosedFormViolation) {
  LmiProblem lmi({2, 1, 2, 2});
  const hinf::lmi::VarId x = lmi.add_scalar("x");
  const hinf::lmi::VarId X = lmi.add_symmetric("X", 2);
  lmi.add_scalar_term(0, 0, x, MatrixXd::Identity(2, 2));
  lmi.add_constant(0, 0, MatrixXd::Identity(2, 2));
  lmi.add_scalar_term(1, 1, x, -MatrixXd::Identity(1, 1));
  lmi.add_constant(1, 1, MatrixXd::Identity(1, 1));
  lmi.add_term(2, 2, X, MatrixXd::Identity(2, 2), MatrixXd::Identity(2, 2));
  lmi.add_constant(2, 2, -MatrixXd::Identity(2, 2));
  lmi.add_term(3, 3, X, -MatrixXd::Identity(2, 2), MatrixXd::Identity(2, 2));
  lmi.add_constant(3, 3, -MatrixXd::Identity(2, 2));
  const hinf::sdp::Options o;
  const hinf::sdp::Solution sol = hinf::sdp::minimize_linear(lmi, lmi.cost_of(x), o);
  ASSERT_EQ(sol.status, hinf::sdp::Status::Infeasible) << sol.detail;
  ASSERT_FALSE(sol.phase1_path.empty());
  const std::vector<VectorXd> earlier(sol.phase1_path.begin(), sol.phase1_path.end() - 1);
  const hinf::sdp::DualBound b =
      hinf::sdp::verified_infeasibility(lmi, sol.phase1_path.back(), o.lmi_margin, {}, earlier);
  ASSERT_TRUE(b.verified) << b.detail;
  EXPECT_LE(b.lower_bound, 1.0) << "a floor above the true s* = 1 is false";
  // phase I stops once its gap is within 1e-3 of s (path_following.cpp): the floor is that tight
  EXPECT_GT(b.lower_bound, 1.0 - 2e-3) << "the certificate should be tight";
}

// [x, 1; 1, 0] ≺ 0 has no solution, but s* = inf λ_max = 0 is approached only as x → −∞:
// phase I (with its ball) may end with s > 0, yet no certificate of infeasibility may claim
// a positive floor — that would be a false exit 3.
TEST(DualBound, NoInfeasibilityCertificateWhenTheInfimumIsZero) {
  LmiProblem lmi({2});
  const hinf::lmi::VarId x = lmi.add_scalar("x");
  MatrixXd K = MatrixXd::Zero(2, 2);
  K(0, 0) = 1;
  lmi.add_scalar_term(0, 0, x, K);
  MatrixXd M0 = MatrixXd::Zero(2, 2);
  M0(0, 1) = M0(1, 0) = 1;
  lmi.add_constant(0, 0, M0);
  const hinf::sdp::Options o;
  const hinf::sdp::Solution sol = hinf::sdp::minimize_linear(lmi, lmi.cost_of(x), o);
  ASSERT_NE(sol.status, hinf::sdp::Status::Solved);
  if (sol.phase1_path.empty()) return;
  const std::vector<VectorXd> earlier(sol.phase1_path.begin(), sol.phase1_path.end() - 1);
  const hinf::sdp::DualBound b =
      hinf::sdp::verified_infeasibility(lmi, sol.phase1_path.back(), o.lmi_margin, {}, earlier);
  EXPECT_FALSE(b.verified && b.lower_bound > 0) << "false certificate: floor " << b.lower_bound;
}

}  // namespace
