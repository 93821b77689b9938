// The generic LMI layer (lmi/): evaluation of M(x) = M0 + Σ xᵢMᵢ against a hand
// assembly, and the cost vector of a scalar variable.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <stdexcept>

#include "hinf/lmi/lmi_problem.hpp"
#include "random_plants.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using hinf::lmi::LmiProblem;
using hinf::test::random_matrix;
using hinf::test::random_symmetric;
using hinf::test::random_vector;
using hinf::test::relative_error;


// ---------------------------------------------------------------- toy LMI
TEST(LmiLayer, ToyLmiEvaluateMatchesHandAssembly) {
  std::mt19937 g(11);
  // blocks 3, 2, 4, 1 (odd and unequal sizes)
  LmiProblem L({3, 2, 4, 1});
  const auto X = L.add_symmetric("X", 3);
  const auto Y = L.add_full("Y", 2, 4);
  const auto z = L.add_scalar("z");
  const auto w = L.add_scalar("w");
  EXPECT_EQ(L.num_params(), 6 + 8 + 1 + 1);
  EXPECT_EQ(L.order(), 10);
  const MatrixXd L00 = random_matrix(g, 3, 3);
  const MatrixXd L02 = random_matrix(g, 3, 2), R02 = random_matrix(g, 4, 4);
  const MatrixXd L12 = random_matrix(g, 2, 4), R12 = random_matrix(g, 2, 4);  // L12 · Yᵀ · R12 at (1,2)
  const MatrixXd L22 = random_matrix(g, 4, 2), R22 = random_matrix(g, 4, 4);  // symmetrised at (2,2)
  const MatrixXd K11 = random_symmetric(g, 2), K01 = random_matrix(g, 3, 2), K33 = MatrixXd::Constant(1, 1, -1.0);
  const MatrixXd C00 = -4 * MatrixXd::Identity(3, 3), C23 = random_matrix(g, 4, 1);
  L.add_term(0, 0, X, L00, L00.transpose());
  L.add_term(0, 2, Y, L02, R02);
  L.add_term(1, 2, Y, L12, R12, /*transpose=*/true);
  L.add_term(2, 2, Y, L22, R22, false, /*symmetrize=*/true);
  L.add_scalar_term(1, 1, z, K11);
  L.add_scalar_term(0, 1, z, K01);
  L.add_scalar_term(3, 3, w, K33);
  L.add_constant(0, 0, C00);
  L.add_constant(2, 3, C23);

  for (int trial = 0; trial < 5; ++trial) {
    VectorXd x = VectorXd::Zero(L.num_params());
    const MatrixXd Xv = random_symmetric(g, 3), Yv = random_matrix(g, 2, 4);
    const double zv = random_matrix(g, 1, 1)(0, 0), wv = random_matrix(g, 1, 1)(0, 0);
    L.set_value(X, Xv, x);
    L.set_value(Y, Yv, x);
    L.set_value(z, MatrixXd::Constant(1, 1, zv), x);
    L.set_value(w, MatrixXd::Constant(1, 1, wv), x);
    EXPECT_LT(relative_error(L.value(X, x), Xv), 1e-15);
    EXPECT_LT(relative_error(L.value(Y, x), Yv), 1e-15);
    EXPECT_EQ(L.value(z, x)(0, 0), zv);

    MatrixXd M = MatrixXd::Zero(10, 10);
    auto put = [&](int r0, int c0, const MatrixXd& B) {
      M.block(r0, c0, B.rows(), B.cols()) += B;
      if (r0 != c0) M.block(c0, r0, B.cols(), B.rows()) += B.transpose();
    };
    // offsets: 0, 3, 5, 9
    put(0, 0, L00 * Xv * L00.transpose() + C00);
    put(0, 5, L02 * Yv * R02);
    put(3, 5, L12 * Yv.transpose() * R12);
    const MatrixXd T22 = L22 * Yv * R22;
    put(5, 5, T22 + T22.transpose());
    put(3, 3, zv * K11);
    put(0, 3, zv * K01);
    put(9, 9, wv * K33);
    put(5, 9, C23);
    EXPECT_LT(relative_error(L.evaluate(x), M), 1e-13) << "trial " << trial;
  }
}

// cost_of(v): cᵀx is the scalar variable's value, for any x; refused for a matrix variable.
TEST(LmiLayer, CostOfScalarVariable) {
  std::mt19937 g(12);
  LmiProblem L({2, 1});
  const auto X = L.add_symmetric("X", 2);
  const auto z = L.add_scalar("z");
  const auto w = L.add_scalar("w");
  const VectorXd x = random_vector(g, L.num_params());
  EXPECT_DOUBLE_EQ(L.cost_of(z).dot(x), L.value(z, x)(0, 0));
  EXPECT_DOUBLE_EQ(L.cost_of(w).dot(x), L.value(w, x)(0, 0));
  EXPECT_EQ(L.cost_of(w).cwiseAbs().sum(), 1.0);
  EXPECT_THROW(L.cost_of(X), std::invalid_argument);
}

}  // namespace

// ---------------------------------------------------------------- Hessian work count
// hessian_multiply_adds() counted by hand for one term: the four products Q₁, P₁, Q₂, P₂,
// the block's update 2·a·b·a·b, the contraction 3·raw² (docs: lmi_problem.hpp).
TEST(LmiLayer, HessianMultiplyAddsCountedByHand) {
  {  // X (2×2) with identity factors: each product is a 2×2 copy
    LmiProblem L({2});
    const auto X = L.add_symmetric("X", 2);
    L.add_term(0, 0, X, MatrixXd::Identity(2, 2), MatrixXd::Identity(2, 2));
    EXPECT_EQ(L.hessian_multiply_adds(), 4 * 4 + 2 * 16 + 3 * 16);
  }
  {  // left 3×2, right 2×3 (neither a scaled identity): each product (2×3)(3×3)(3×2) costs 18 + 12
    std::mt19937 g(3);
    LmiProblem L({3});
    const auto X = L.add_full("X", 2, 2);
    L.add_term(0, 0, X, random_matrix(g, 3, 2), random_matrix(g, 2, 3), false, true);
    EXPECT_EQ(L.hessian_multiply_adds(), 4 * 30 + 2 * 16 + 3 * 16);
  }
}
