// Seeded random test problems shared by the synthesis tests.
#pragma once
#include <Eigen/Dense>
#include <random>

#include "hinf/models/plant.hpp"

namespace hinf::test {

// A random r×c matrix with N(0, 1) entries (column-major draw order, so a seed gives
// the same matrix everywhere).
inline Eigen::MatrixXd random_matrix(std::mt19937& g, int r, int c) {
  std::normal_distribution<double> N(0, 1);
  Eigen::MatrixXd M(r, c);
  for (int j = 0; j < c; ++j)
    for (int i = 0; i < r; ++i) M(i, j) = N(g);
  return M;
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

}  // namespace hinf::test
