// LtiFilter / FixedLtiFilter against docs/maths.md (5)–(6), checked with hand-written loops and
// closed forms (not with the filter's own Eigen expressions).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "hinf/runtime/lti_filter.hpp"

using hinf::runtime::FixedLtiFilter;
using hinf::runtime::LtiFilter;
using hinf::runtime::LtiGainsError;

namespace {

Eigen::MatrixXd random_matrix(int r, int c, std::mt19937& g) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd M(r, c);
  for (int j = 0; j < c; ++j)
    for (int i = 0; i < r; ++i) M(i, j) = u(g);
  return M;
}

// A random matrix scaled to spectral radius 0.9 (scaling by the Frobenius norm bounds it).
Eigen::MatrixXd random_stable(int n, std::mt19937& g) {
  Eigen::MatrixXd A = random_matrix(n, n, g);
  return 0.9 * A / A.norm();
}

// The paper's published gains (docs/maths.md (78)–(80)).
void paper_gains(Eigen::MatrixXd& A_F, Eigen::MatrixXd& B_F, Eigen::MatrixXd& C_F) {
  A_F.resize(6, 6);
  A_F << -0.6126, -0.0053, -0.0046, 0.1, -1.7e-6, -1.0e-6,  //
      -0.0052, -0.6083, -0.0035, -1.5e-6, 0.1, -1.4e-6,     //
      -0.0046, -0.0035, -0.6066, -1.5e-6, -5.6e-7, 0.1,     //
      -6.1302, -0.0390, -0.0337, 0.9980, 1.1e-4, 8.2e-5,    //
      -0.0385, -6.0991, -0.0259, 8.0e-5, 0.9979, 6.3e-5,    //
      -0.0337, -0.0259, -6.0864, 8.3e-5, 6.4e-5, 0.9979;
  B_F.resize(6, 3);
  B_F << -1.6126, -0.0053, -0.0046, -0.0052, -1.6083, -0.0035, -0.0046, -0.0035, -1.6066,  //
      -6.1300, -0.0390, -0.0337, -0.0385, -6.0989, -0.0259, -0.0337, -0.0259, -6.0862;
  C_F.resize(6, 6);
  C_F << -1e6, 0.0489, 0.0247, 6.3345, -5.4934, -4.3894,  //
      0.0386, -1e6, 0.0418, -5.3662, 10.3349, -2.9326,    //
      0.0420, 0.0148, -1e6, -4.5742, -2.9659, 11.3677,    //
      -0.3164, 0.3131, 0.1588, -999960, -33.635, -28.487, //
      0.2469, -0.5593, 0.2630, -33.612, -999935, -19.564, //
      0.2712, 0.0939, -0.5821, -28.520, -19.572, -999927;
  C_F *= 1e-6;
}

using Mat = std::vector<std::vector<double>>;
Mat to_nested(const Eigen::MatrixXd& M) {
  Mat out(M.rows(), std::vector<double>(M.cols()));
  for (int i = 0; i < M.rows(); ++i)
    for (int j = 0; j < M.cols(); ++j) out[i][j] = M(i, j);
  return out;
}

}  // namespace

TEST(LtiFilter, ScalarClosedForm) {
  // x_k = a^k x_0 + sum_{i<k} a^(k-1-i) b y_i,  z_k = c x_k  (z_k uses y_0..y_{k-1} only).
  const double a = -0.7, b = 1.3, c = 2.5, x0 = 0.4;
  Eigen::MatrixXd A(1, 1), B(1, 1), C(1, 1);
  A << a;
  B << b;
  C << c;
  LtiFilter f(A, B, C);
  Eigen::VectorXd z0(1);
  z0 << c * x0;
  f.init(z0);
  EXPECT_NEAR(f.x_F()(0), x0, 1e-15);
  std::mt19937 g(1);
  std::normal_distribution<double> nd;
  std::vector<double> ys;
  for (int k = 0; k < 50; ++k) {
    double xk = std::pow(a, k) * x0;
    for (int i = 0; i < k; ++i) xk += std::pow(a, k - 1 - i) * b * ys[i];
    Eigen::VectorXd y(1);
    y << nd(g);
    ys.push_back(y(0));
    const double z = f.step(y)(0);
    EXPECT_NEAR(z, c * xk, 1e-12 * (1.0 + std::abs(c * xk))) << "k = " << k;
  }
}

TEST(LtiFilter, MatchesHandWrittenLoopsAndOrderOfEquation12) {
  std::mt19937 g(7);
  const int n = 5, m = 2, l = 3;
  const Eigen::MatrixXd A = random_stable(n, g), B = random_matrix(n, m, g), C = random_matrix(l, n, g);
  LtiFilter f(A, B, C);
  const Mat a = to_nested(A), b = to_nested(B), c = to_nested(C);
  std::vector<double> x(n, 0.0);
  Eigen::VectorXd x0 = random_matrix(n, 1, g);
  f.set_state(x0);
  for (int i = 0; i < n; ++i) x[i] = x0(i);
  std::normal_distribution<double> nd;
  for (int k = 0; k < 200; ++k) {
    Eigen::VectorXd y(m);
    for (int i = 0; i < m; ++i) y(i) = nd(g);
    std::vector<double> z(l, 0.0), xn(n, 0.0);
    for (int i = 0; i < l; ++i)
      for (int j = 0; j < n; ++j) z[i] += c[i][j] * x[j];
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) xn[i] += a[i][j] * x[j];
      for (int j = 0; j < m; ++j) xn[i] += b[i][j] * y(j);
    }
    const Eigen::VectorXd zf = f.step(y);
    for (int i = 0; i < l; ++i) EXPECT_NEAR(zf(i), z[i], 1e-12) << "k = " << k;
    x = xn;
    for (int i = 0; i < n; ++i) EXPECT_NEAR(f.x_F()(i), x[i], 1e-12);
  }
  EXPECT_THROW(f.step(Eigen::VectorXd::Zero(m + 1)), std::invalid_argument);
}

TEST(LtiFilter, FixedAndDynamicAgree) {
  std::mt19937 g(11);
  const Eigen::MatrixXd A = random_stable(6, g), B = random_matrix(6, 3, g), C = random_matrix(6, 6, g);
  LtiFilter fd(A, B, C);
  FixedLtiFilter<6, 3, 6> ff(A, B, C);
  Eigen::VectorXd z0 = random_matrix(6, 1, g);
  fd.init(z0);
  ff.init(z0);
  std::normal_distribution<double> nd;
  for (int k = 0; k < 300; ++k) {
    Eigen::Vector3d y(nd(g), nd(g), nd(g));
    const Eigen::VectorXd zd = fd.step(y);
    const Eigen::Matrix<double, 6, 1> zf = ff.step(y);
    EXPECT_LE((zd - zf).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + zd.cwiseAbs().maxCoeff()));
  }
  EXPECT_NEAR(fd.spectral_radius(), ff.spectral_radius(), 1e-15);
}

TEST(LtiFilter, FixedFloatVariantTracksDouble) {
  std::mt19937 g(12);
  const Eigen::MatrixXd A = random_stable(4, g), B = random_matrix(4, 2, g), C = random_matrix(2, 4, g);
  LtiFilter fd(A, B, C);
  FixedLtiFilter<4, 2, 2, float> ff(A.cast<float>(), B.cast<float>(), C.cast<float>());
  std::normal_distribution<double> nd;
  for (int k = 0; k < 100; ++k) {
    Eigen::Vector2d y(nd(g), nd(g));
    const Eigen::VectorXd zd = fd.step(y);
    const Eigen::Vector2f zf = ff.step(y.cast<float>());
    EXPECT_LE((zd - zf.cast<double>()).cwiseAbs().maxCoeff(), 1e-4 * (1.0 + zd.cwiseAbs().maxCoeff()));
  }
}

TEST(LtiFilter, InitUsesPseudoInverseFullColumnRank) {
  // Tall C_F (l > n), full column rank: C^+ = (C^T C)^-1 C^T (normal equations, here
  // solved by an explicit inverse in the test only).
  std::mt19937 g(3);
  const Eigen::MatrixXd A = random_stable(3, g), B = random_matrix(3, 2, g), C = random_matrix(5, 3, g);
  LtiFilter f(A, B, C);
  const Eigen::VectorXd z0 = random_matrix(5, 1, g);
  f.init(z0);
  const Eigen::VectorXd expect = (C.transpose() * C).inverse() * C.transpose() * z0;
  EXPECT_LE((f.x_F() - expect).norm(), 1e-12 * expect.norm());
}

TEST(LtiFilter, InitUsesPseudoInverseFullRowRank) {
  // Wide C_F (l < n), full row rank: C^+ = C^T (C C^T)^-1, so C_F x_F(0) = z0 exactly.
  std::mt19937 g(4);
  const Eigen::MatrixXd A = random_stable(5, g), B = random_matrix(5, 2, g), C = random_matrix(2, 5, g);
  LtiFilter f(A, B, C);
  const Eigen::VectorXd z0 = random_matrix(2, 1, g);
  f.init(z0);
  const Eigen::VectorXd expect = C.transpose() * (C * C.transpose()).inverse() * z0;
  EXPECT_LE((f.x_F() - expect).norm(), 1e-12 * expect.norm());
  EXPECT_LE((C * f.x_F() - z0).norm(), 1e-12 * z0.norm());
}

TEST(LtiFilter, PseudoInverseRankDeficientSatisfiesPenroseConditions) {
  std::mt19937 g(5);
  const Eigen::MatrixXd U = random_matrix(6, 2, g), V = random_matrix(2, 4, g);
  const Eigen::MatrixXd C = U * V;  // 6x4, rank 2
  LtiFilter f(random_stable(4, g), random_matrix(4, 3, g), C);
  const Eigen::MatrixXd& X = f.C_F_pinv();
  ASSERT_EQ(X.rows(), 4);
  ASSERT_EQ(X.cols(), 6);
  const double tol = 1e-11 * (1.0 + C.norm() * X.norm());
  EXPECT_LE((C * X * C - C).norm(), tol);
  EXPECT_LE((X * C * X - X).norm(), tol * X.norm());
  EXPECT_LE(((C * X).transpose() - C * X).norm(), tol);
  EXPECT_LE(((X * C).transpose() - X * C).norm(), tol);
}

TEST(LtiFilter, PaperGainsAreAccepted) {
  Eigen::MatrixXd A_F, B_F, C_F;
  paper_gains(A_F, B_F, C_F);
  const auto v = LtiFilter::validate(A_F, B_F, C_F);
  EXPECT_TRUE(v.ok()) << v.message;
  EXPECT_LT(v.spectral_radius, 1.0);
  // C_F ~ -I: init reproduces z0 to the accuracy of C_F's conditioning.
  LtiFilter f(A_F, B_F, C_F);
  Eigen::VectorXd z0(6);
  z0 << 630, 520, 1000, 0, 0, 0;
  f.init(z0);
  EXPECT_LE((C_F * f.x_F() - z0).norm(), 1e-9 * z0.norm());
}

TEST(LtiFilterValidation, ShapeErrorsNameMatrixAndDims) {
  const Eigen::MatrixXd I6 = 0.5 * Eigen::MatrixXd::Identity(6, 6);
  auto expect_msg = [](const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                       LtiGainsError code, const std::string& name, const std::string& dims) {
    const auto v = LtiFilter::validate(A, B, C);
    EXPECT_EQ(v.error, code) << v.message;
    EXPECT_NE(v.message.find(name), std::string::npos) << v.message;
    EXPECT_NE(v.message.find(dims), std::string::npos) << v.message;
    try {
      LtiFilter f(A, B, C);
      ADD_FAILURE() << "no exception for " << name;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  expect_msg(Eigen::MatrixXd::Zero(6, 5), Eigen::MatrixXd::Zero(6, 3), Eigen::MatrixXd::Zero(6, 6),
             LtiGainsError::ShapeMismatch, "A_F", "6x5");
  expect_msg(I6, Eigen::MatrixXd::Zero(5, 3), Eigen::MatrixXd::Zero(6, 6), LtiGainsError::ShapeMismatch, "B_F", "5x3");
  expect_msg(I6, Eigen::MatrixXd::Zero(6, 3), Eigen::MatrixXd::Zero(6, 4), LtiGainsError::ShapeMismatch, "C_F", "6x4");
  expect_msg(Eigen::MatrixXd(0, 0), Eigen::MatrixXd::Zero(0, 3), Eigen::MatrixXd::Zero(6, 0),
             LtiGainsError::EmptyDimension, "A_F", "0x0");
  // Fixed-size filter: shapes checked against the template dimensions.
  try {
    FixedLtiFilter<6, 3, 6> f(I6, Eigen::MatrixXd::Zero(6, 2), Eigen::MatrixXd::Zero(6, 6));
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("B_F must be 6x3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("6x2"), std::string::npos) << e.what();
  }
}

TEST(LtiFilterValidation, NonFiniteNamesMatrixAndEntry) {
  Eigen::MatrixXd A = 0.5 * Eigen::MatrixXd::Identity(3, 3), B = Eigen::MatrixXd::Ones(3, 1), C = Eigen::MatrixXd::Ones(1, 3);
  C(0, 2) = std::numeric_limits<double>::quiet_NaN();
  auto v = LtiFilter::validate(A, B, C);
  EXPECT_EQ(v.error, LtiGainsError::NonFinite);
  EXPECT_NE(v.message.find("C_F"), std::string::npos) << v.message;
  EXPECT_NE(v.message.find("(0, 2)"), std::string::npos) << v.message;
  C(0, 2) = 1.0;
  B(1, 0) = std::numeric_limits<double>::infinity();
  v = LtiFilter::validate(A, B, C);
  EXPECT_EQ(v.error, LtiGainsError::NonFinite);
  EXPECT_NE(v.message.find("B_F"), std::string::npos) << v.message;
}

TEST(LtiFilterValidation, SchurStabilityIsStrict) {
  const Eigen::MatrixXd B = Eigen::MatrixXd::Ones(2, 1), C = Eigen::MatrixXd::Ones(1, 2);
  // Rotation by 0.3 rad scaled by r: eigenvalues r e^{+-0.3i}, spectral radius r.
  auto rot = [](double r) {
    Eigen::MatrixXd A(2, 2);
    A << r * std::cos(0.3), -r * std::sin(0.3), r * std::sin(0.3), r * std::cos(0.3);
    return A;
  };
  auto v = LtiFilter::validate(rot(0.999), B, C);
  EXPECT_TRUE(v.ok()) << v.message;
  EXPECT_NEAR(v.spectral_radius, 0.999, 1e-12);
  v = LtiFilter::validate(rot(1.0), B, C);
  EXPECT_EQ(v.error, LtiGainsError::NotSchurStable);
  v = LtiFilter::validate(rot(1.25), B, C);
  EXPECT_EQ(v.error, LtiGainsError::NotSchurStable);
  EXPECT_NEAR(v.spectral_radius, 1.25, 1e-12);
  EXPECT_NE(v.message.find("spectral radius 1.25"), std::string::npos) << v.message;
  EXPECT_NE(v.message.find("A_F"), std::string::npos) << v.message;
  EXPECT_THROW(LtiFilter(rot(1.25), B, C), std::invalid_argument);
}
