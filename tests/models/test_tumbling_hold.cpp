// The tumbling_hold design model (docs/maths.md (157)–(160)) and Tustin's rule for a
// controller (161): against matrices and responses worked out independently.
#include <gtest/gtest.h>

#include <complex>

#include "hinf/models/controller.hpp"
#include "hinf/models/tumbling_hold.hpp"

namespace {

using hinf::models::kRadiansPerDegree;

// Flat spin about z at w: K = diag(w², w², 0), 2W = [[0, 2w, 0], [−2w, 0, 0], 0] (by hand:
// −[ω×]² = |ω|² I − ω ωᵀ, −2[ω×] for ω = (0, 0, w)).
TEST(TumblingHoldModel, FlatSpinMatricesByHand) {
  const hinf::models::TumblingHoldModel m;
  const hinf::GeneralisedPlant P = hinf::models::tumbling_hold_plant(m);
  const double w = 2 * kRadiansPerDegree;
  ASSERT_EQ(P.n(), 6);
  ASSERT_EQ(P.nw(), 6);
  ASSERT_EQ(P.nz(), 9);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, 6);
  A.block(0, 3, 3, 3).setIdentity();
  A(3, 0) = w * w;
  A(4, 1) = w * w;
  A(3, 4) = 2 * w;
  A(4, 3) = -2 * w;
  EXPECT_LE((P.A - A).cwiseAbs().maxCoeff(), 1e-18);
  EXPECT_DOUBLE_EQ(P.B2(3, 0), 1.0 / 500);
  EXPECT_DOUBLE_EQ(P.B1(5, 2), 1e-4);
  EXPECT_DOUBLE_EQ(P.D21(2, 5), 0.01);
  EXPECT_DOUBLE_EQ(P.D12(8, 2), 0.8);
  EXPECT_DOUBLE_EQ(P.C1(0, 0), 1.0);
  // the equilibrium force of ρ* = [3, 0, 0]: −m w² 3 along x (the centripetal force, 1.83 N)
  const Eigen::Vector3d U = hinf::models::equilibrium_force(500, Eigen::Vector3d(0, 0, w), Eigen::Vector3d::Zero(),
                                                            Eigen::Vector3d(3, 0, 0));
  EXPECT_NEAR(U(0), -500 * w * w * 3, 1e-15);
  EXPECT_NEAR(U(0), -1.8277, 1e-4);
  EXPECT_EQ(U(1), 0);
}

// The stiffness against a direct evaluation of −ω̇×ρ − ω×(ω×ρ) at a random ρ.
TEST(TumblingHoldModel, StiffnessIsTheRotatingFrameAcceleration) {
  const Eigen::Vector3d w(0.01, -0.02, 0.03), wd(1e-4, 2e-4, -3e-4), rho(1.5, -2.0, 0.7);
  const Eigen::Vector3d direct = -wd.cross(rho) - w.cross(w.cross(rho));
  EXPECT_LE((hinf::models::rotating_frame_stiffness(w, wd) * rho - direct).norm(), 1e-17);
}

// The robust channel's scales: the worked example of docs/maths.md (160) (|δω| = 0.1 °/s about
// 2 °/s, n = 1.1016e-3): e1 = √2 (2|ω₀||δω| + |δω|² + 3n²) = 1.82e-4, e2 = √2·2|δω| = 4.94e-3.
TEST(TumblingHoldModel, UncertaintyScales) {
  const hinf::models::TumblingHoldModel m;
  hinf::models::TumblingHoldUncertainty u;
  u.rate = 0.1 * kRadiansPerDegree;
  const hinf::UncertaintyChannel c = hinf::models::tumbling_hold_uncertainty(m, u, 6);
  EXPECT_NEAR(c.E(0, 0), 1.817e-4, 0.001e-4);
  EXPECT_NEAR(c.E(3, 3), 4.936e-3, 0.001e-3);
  EXPECT_EQ(c.H(3, 0), 1.0);
  EXPECT_EQ(c.H(0, 0), 0.0);
}

// Tustin: the discrete frequency response at z = e^{jθ} equals the continuous one at
// s = (2/T)(z − 1)/(z + 1), for a random controller with D_K ≠ 0.
TEST(Tustin, FrequencyResponseIsTheBilinearMap) {
  std::srand(3);
  hinf::Controller K;
  K.A_K = Eigen::MatrixXd::Random(4, 4) - 2 * Eigen::MatrixXd::Identity(4, 4);
  K.B_K = Eigen::MatrixXd::Random(4, 2);
  K.C_K = Eigen::MatrixXd::Random(3, 4);
  K.D_K = Eigen::MatrixXd::Random(3, 2);
  const double T = 0.1;
  const hinf::Controller D = hinf::tustin(K, T);
  using C = std::complex<double>;
  const auto response = [](const hinf::Controller& k, C x) {
    const Eigen::MatrixXcd I = Eigen::MatrixXcd::Identity(k.A_K.rows(), k.A_K.cols());
    return Eigen::MatrixXcd(k.C_K.cast<C>() * (x * I - k.A_K.cast<C>()).inverse() * k.B_K.cast<C>() +
                            k.D_K.cast<C>());
  };
  for (double theta : {1e-3, 0.05, 0.5, 1.5, 3.0}) {
    const C z = std::polar(1.0, theta);
    const C s = (2 / T) * (z - 1.0) / (z + 1.0);
    EXPECT_LE((response(D, z) - response(K, s)).norm(), 1e-12 * response(K, s).norm()) << theta;
  }
}

}  // namespace
