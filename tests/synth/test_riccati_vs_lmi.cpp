// At zero uncertainty (H = E = 0) Corollary 1's optimum is the optimal H∞ a priori
// (one-step predictor) level, which the stationary game Riccati equation gives by
// bisection with no LMI involved (riccati_filter.hpp). Our γ must match it.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <exception>
#include <random>

#include "hinf/synth/config.hpp"
#include "hinf/certify/riccati_filter.hpp"
#include "hinf/synth/synthesis.hpp"
#include "random_plants.hpp"

namespace {

using Eigen::MatrixXd;
using hinf::Plant;

Plant random_nominal_plant(std::mt19937& g, int n, int p, int m, int q, int l, double rho) {
  using hinf::test::random_matrix;
  Plant P;
  P.A = random_matrix(g, n, n);
  P.A *= rho / P.A.operatorNorm();
  P.B = random_matrix(g, n, p);
  P.C = random_matrix(g, m, n);
  P.D = random_matrix(g, m, q);  // q ≥ m: D D^T > 0 almost surely (the Riccati form needs R > 0)
  P.L = random_matrix(g, l, n);
  P.H = MatrixXd(n, 0);
  P.E = MatrixXd(0, n);
  return P;
}

void expect_same_gamma(const Plant& P) {
  const double g_ric = hinf::certify::optimal_hinf_predictor_gamma(P, 1e-10);
  hinf::synth::SynthesisResult res;
  try {
    res = hinf::synth::synthesize(P, hinf::synth::Settings{});
  } catch (const std::exception& e) {
    ADD_FAILURE() << "synthesize threw: " << e.what() << " (Riccati γ = " << g_ric << ")";
    return;
  }
  std::printf("  LMI γ = %.10g, Riccati γ = %.10g, rel diff %.2e\n", res.gamma, g_ric,
              (res.gamma - g_ric) / g_ric);
  EXPECT_NEAR(res.gamma, g_ric, 1e-5 * g_ric) << "LMI " << res.gamma << "  Riccati " << g_ric
                                              << "  rel diff " << (res.gamma - g_ric) / g_ric;
  EXPECT_TRUE(res.certificate.passed);
}

TEST(RiccatiVsLmi, RandomNominalPlants) {
  std::mt19937 g(4242);
  struct D { int n, p, m, q, l; double rho; };
  const D dims[] = {{2, 1, 1, 1, 1, 0.5}, {3, 2, 1, 2, 2, 0.8}, {4, 2, 2, 2, 4, 0.9},
                    {5, 3, 2, 3, 2, 0.7}, {6, 2, 3, 3, 3, 0.95}};
  for (const D& d : dims) {
    SCOPED_TRACE(testing::Message() << "n=" << d.n << " p=" << d.p << " m=" << d.m << " q=" << d.q
                                    << " l=" << d.l << " |A|=" << d.rho);
    expect_same_gamma(random_nominal_plant(g, d.n, d.p, d.m, d.q, d.l, d.rho));
  }
}

// The paper's plant with the uncertainty removed (δ̄ = 0).
TEST(RiccatiVsLmi, PaperPlantNominal) {
  Plant P = hinf::synth::load_config(std::string(HINF_SOURCE_DIR) + "/configs/paper-dbar0.05.yaml").plant;
  P.H = MatrixXd(P.n(), 0);
  P.E = MatrixXd(0, P.n());
  expect_same_gamma(P);
}

}  // namespace
