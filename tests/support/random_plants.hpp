// Seeded random test problems shared by the tests of every layer (one generator: normal
// entries drawn column by column, so a seed gives the same matrix everywhere).
#pragma once
#include <Eigen/Dense>
#include <algorithm>
#include <random>

#include "hinf/models/plant.hpp"

namespace hinf::test {

// A random r×c matrix with N(0, 1) entries (column-major draw order, so a seed gives
// the same matrix everywhere). Any standard engine (std::mt19937, std::mt19937_64).
template <class Engine>
Eigen::MatrixXd random_matrix(Engine& g, int r, int c) {
  std::normal_distribution<double> N(0, 1);
  Eigen::MatrixXd M(r, c);
  for (int j = 0; j < c; ++j)
    for (int i = 0; i < r; ++i) M(i, j) = N(g);
  return M;
}

// A random symmetric n×n matrix (M + Mᵀ)/2 and a random n-vector, drawn as random_matrix.
template <class Engine>
Eigen::MatrixXd random_symmetric(Engine& g, int n) {
  const Eigen::MatrixXd M = random_matrix(g, n, n);
  return 0.5 * (M + M.transpose());
}
template <class Engine>
Eigen::VectorXd random_vector(Engine& g, int n) {
  return random_matrix(g, n, 1);
}

// max |A − B| relative to max(1, max |B|): the comparison of the derivative tests.
inline double relative_error(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  return (A - B).cwiseAbs().maxCoeff() / std::max(1.0, B.cwiseAbs().maxCoeff());
}

// Uncertain plant of order n with A + H F E Schur for every ‖F‖ ≤ 1: ‖A‖₂ = 0.6 and
// ‖H‖₂‖E‖₂ = 0.3, so ‖A + HFE‖₂ ≤ 0.9. H and E are deliberately unbalanced (‖H‖ = 30,
// ‖E‖ = 0.01); the other dimensions are drawn from 1..3.
inline hinf::Plant random_uncertain_plant(std::mt19937& g, int n) {
  std::uniform_int_distribution<int> dim(1, 3);
  const int p = dim(g), m = dim(g), q = dim(g), l = dim(g), j = dim(g), k = dim(g);
  hinf::Plant P;
  P.A = random_matrix(g, n, n);
  P.A *= 0.6 / P.A.operatorNorm();
  P.B = random_matrix(g, n, p);
  P.C = random_matrix(g, m, n);
  P.D = 0.3 * random_matrix(g, m, q);
  P.L = random_matrix(g, l, n);
  P.H = random_matrix(g, n, j);
  P.H *= 30.0 / P.H.operatorNorm();
  P.E = random_matrix(g, k, n);
  P.E *= 0.01 / P.E.operatorNorm();
  return P;
}

// A filter of the plant's dimensions with ‖A_F‖₂ = 0.5 (so the error system of a
// robustly stable plant is robustly stable) — not an optimal one.
inline hinf::Filter random_stable_filter(std::mt19937& g, const hinf::Plant& P) {
  hinf::Filter F;
  F.A_F = random_matrix(g, P.n(), P.n());
  F.A_F *= 0.5 / F.A_F.operatorNorm();
  F.B_F = random_matrix(g, P.n(), P.m());
  F.C_F = random_matrix(g, P.l(), P.n());
  return F;
}

// A random n×n matrix scaled to spectral radius rho (Schur stable for rho < 1).
template <class Engine>
Eigen::MatrixXd random_stable_matrix(Engine& g, int n, double rho) {
  const Eigen::MatrixXd A = random_matrix(g, n, n);
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
  return A * (rho / es.eigenvalues().cwiseAbs().maxCoeff());
}

// A plant with the given dimensions, ‖A‖₂ = 0.7; with j > 0 an uncertainty H (0.3·N(0,1))
// and E (1e-3·N(0,1)) deliberately unbalanced, else none (H n×0, E 0×n).
inline hinf::Plant random_plant_with_dimensions(std::mt19937& g, int n, int p, int m, int q, int l, int j, int k) {
  hinf::Plant P;
  P.A = random_matrix(g, n, n);
  P.A *= 0.7 / P.A.operatorNorm();
  P.B = random_matrix(g, n, p);
  P.C = random_matrix(g, m, n);
  P.D = random_matrix(g, m, q);
  P.L = random_matrix(g, l, n);
  if (j > 0) {
    P.H = 0.3 * random_matrix(g, n, j);
    P.E = 1e-3 * random_matrix(g, k, n);
  } else {
    P.H = Eigen::MatrixXd(n, 0);
    P.E = Eigen::MatrixXd(0, n);
  }
  return P;
}

// A nominal plant (no uncertainty) with ρ(A) = rho and D = I + 0.3·N(0,1) (m×m), from its
// own 64-bit engine seeded with `seed`.
inline hinf::Plant random_nominal_plant(int n, int p, int m, int l, double rho, unsigned seed) {
  std::mt19937_64 rng(seed);
  hinf::Plant pl;
  pl.A = random_stable_matrix(rng, n, rho);
  pl.B = random_matrix(rng, n, p);
  pl.C = random_matrix(rng, m, n);
  pl.D = random_matrix(rng, m, m) * 0.3 + Eigen::MatrixXd::Identity(m, m);
  pl.L = random_matrix(rng, l, n);
  pl.H.resize(n, 0);
  pl.E.resize(0, n);
  return pl;
}

}  // namespace hinf::test
