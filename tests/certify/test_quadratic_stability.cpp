// The witness that A + H F E is not quadratically stable (certify/quadratic_stability.hpp,
// docs/maths.md §3.7): closed forms, refusals below gain 1, the same verdict for similarity
// twins, and the destabilising complex perturbation of eq. (119) built independently.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <random>

#include "hinf/certify/quadratic_stability.hpp"
#include "random_plants.hpp"

namespace {

using Eigen::MatrixXcd;
using Eigen::MatrixXd;

// A = 0.9·rot(π/2), H = e₁, E = e·e₁ᵀ: E (zI − A)⁻¹ H = e z / (z² + 0.81), peak e/0.19 at z = j.
struct Rotation {
  MatrixXd A{2, 2}, H{2, 1}, E{1, 2};
  explicit Rotation(double e) {
    A << 0, -0.9, 0.9, 0;
    H << 1, 0;
    E << e, 0;
  }
};

TEST(QuadraticStabilityWitness, ClosedFormGain) {
  for (double e : {0.3, 0.5, 2.0}) {
    SCOPED_TRACE(e);
    const Rotation r(e);
    const double exact = e / 0.19;
    const hinf::certify::GainWitness w = hinf::certify::uncertainty_gain_witness(r.A, r.H, r.E);
    ASSERT_TRUE(w.verified);
    EXPECT_LE(w.gain_lower_bound, exact * (1 + 1e-12)) << "a lower bound above the exact gain is false";
    EXPECT_GE(w.gain_lower_bound, exact * (1 - 1e-9));
    EXPECT_NEAR(w.theta, M_PI / 2, 1e-4);
  }
}

TEST(QuadraticStabilityWitness, NoWitnessBelowGainOne) {
  const Rotation r(0.15);  // peak 0.79
  const hinf::certify::GainWitness w = hinf::certify::uncertainty_gain_witness(r.A, r.H, r.E);
  EXPECT_FALSE(w.verified);
  EXPECT_NEAR(w.gain, 0.15 / 0.19, 1e-7);
  const hinf::certify::GainWitness none =
      hinf::certify::uncertainty_gain_witness(r.A, MatrixXd::Zero(2, 1), r.E);
  EXPECT_FALSE(none.verified);
}

// x → T x: the channel's transfer function, so the verdict and the bound, do not change.
TEST(QuadraticStabilityWitness, SameVerdictForSimilarityTwins) {
  std::mt19937 g(7);
  int verified = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const int n = 3 + trial % 3;
    MatrixXd A = hinf::test::random_matrix(g, n, n);
    A *= 0.8 / std::abs(Eigen::EigenSolver<MatrixXd>(A).eigenvalues().array().abs().maxCoeff());
    const MatrixXd H = hinf::test::random_matrix(g, n, 2), E = (trial % 2 ? 3.0 : 0.05) * hinf::test::random_matrix(g, 2, n);
    MatrixXd T = hinf::test::random_matrix(g, n, n);
    for (int i = 0; i < n; ++i) T.row(i) *= std::pow(10.0, 3.0 * (i - 1.0) / n);
    const MatrixXd Ti = T.inverse();
    const hinf::certify::GainWitness w0 = hinf::certify::uncertainty_gain_witness(A, H, E);
    const hinf::certify::GainWitness w1 = hinf::certify::uncertainty_gain_witness(T * A * Ti, T * H, E * Ti);
    SCOPED_TRACE(testing::Message() << "trial " << trial << " gain " << w0.gain);
    EXPECT_EQ(w0.verified, w0.gain > 1.001);
    EXPECT_EQ(w0.verified, w1.verified);
    EXPECT_NEAR(w0.gain, w1.gain, 1e-6 * w0.gain);
    verified += w0.verified;
  }
  EXPECT_EQ(verified, 3) << "the trials alternate gains well above and well below 1";
}

// Eq. (119)'s mechanism, independently: with G(z)u = σv at the peak, the complex F₀ = u vᴴ/σ
// (‖F₀‖ = 1/σ < 1) puts z = e^{jθ} on the spectrum of A + H F₀ E.
TEST(QuadraticStabilityWitness, ComplexPerturbationReachesTheUnitCircle) {
  const Rotation r(0.5);
  const hinf::certify::GainWitness w = hinf::certify::uncertainty_gain_witness(r.A, r.H, r.E);
  ASSERT_TRUE(w.verified);
  const std::complex<double> z = std::polar(1.0, w.theta);
  MatrixXcd K = -r.A.cast<std::complex<double>>();
  K.diagonal().array() += z;
  const MatrixXcd G = r.E.cast<std::complex<double>>() * K.inverse() * r.H.cast<std::complex<double>>();
  Eigen::JacobiSVD<MatrixXcd> svd(G, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const double sigma = svd.singularValues()(0);
  const MatrixXcd F0 = svd.matrixV().col(0) * svd.matrixU().col(0).adjoint() / sigma;
  const MatrixXcd Ap = r.A.cast<std::complex<double>>() + r.H.cast<std::complex<double>>() * F0 *
                                                              r.E.cast<std::complex<double>>();
  const Eigen::VectorXcd ev = Eigen::ComplexEigenSolver<MatrixXcd>(Ap).eigenvalues();
  EXPECT_LT((ev.array() - z).abs().minCoeff(), 1e-10);
  EXPECT_LT(1.0 / sigma, 1.0);
}

}  // namespace
