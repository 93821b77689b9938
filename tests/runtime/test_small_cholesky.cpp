// The filters' small Cholesky kernels (runtime/include/hinf/runtime/detail/small_cholesky.hpp)
// against Eigen::LLT itself: the same factor and the same solves bit for bit (every sign of
// zero too) on random SPD matrices of sizes 1 … 9 and right-hand sides of 1 … 15 columns —
// the sizes of S, of the REKF's γ²I − L P L^T and of the covariances, and sizes that take
// one, two and three of the triangular solve's panels — and the same verdict on matrices
// that are not positive definite.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cstring>
#include <limits>
#include <random>

#include "hinf/runtime/detail/covariance.hpp"
#include "hinf/runtime/detail/small_cholesky.hpp"

namespace {

template <class M>
bool bitwise_equal(const M& a, const M& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

template <int N>
Eigen::Matrix<double, N, N> random_spd(std::mt19937_64& rng, double conditioning) {
  std::normal_distribution<double> g;
  Eigen::Matrix<double, N, N> A;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) A(i, j) = g(rng);
  Eigen::Matrix<double, N, N> S = A * A.transpose();
  S.diagonal().array() += conditioning;
  return S;
}

template <int N>
using Llt = Eigen::LLT<Eigen::Matrix<double, N, N>>;

template <int N, int M>
void check_size(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix<double, N, N> S = random_spd<N>(rng, trial % 2 ? 1e-6 : 1.0);
    Eigen::Matrix<double, N, M> B;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < M; ++j) B(i, j) = trial == 3 && j == 0 ? 0.0 : g(rng);  // a zero column: signs of zeros
    const Eigen::LLT<Eigen::Matrix<double, N, N>> eigen(S);
    ASSERT_EQ(eigen.info(), Eigen::Success);
    const hinf::runtime::detail::SmallLlt<N> small(S);
    ASSERT_TRUE(small.ok());
    Eigen::Matrix<double, N, N> L = S;
    ASSERT_TRUE(hinf::runtime::detail::cholesky_in_place(L));
    const Eigen::Matrix<double, N, N> eigen_L = eigen.matrixL();
    const Eigen::Matrix<double, N, N> small_L = L.template triangularView<Eigen::Lower>();
    EXPECT_TRUE(bitwise_equal(small_L, eigen_L)) << "N = " << N << ", trial " << trial;
    const Eigen::Matrix<double, N, M> x_eigen = eigen.solve(B), x_small = small.solve(B);
    EXPECT_TRUE(bitwise_equal(x_small, x_eigen)) << "N = " << N << ", M = " << M << ", trial " << trial;
    const Eigen::Matrix<double, N, 1> v = B.col(M - 1);
    const Eigen::Matrix<double, N, 1> w_eigen = eigen.matrixL().solve(v), w_small = small.lower_solve(v);
    EXPECT_TRUE(bitwise_equal(w_small, w_eigen)) << "N = " << N << ", trial " << trial;
  }
  // not positive definite: a negative eigenvalue, and a singular matrix
  Eigen::Matrix<double, N, N> indefinite = random_spd<N>(rng, 1.0);
  indefinite(N - 1, N - 1) = -1.0 - indefinite.row(N - 1).squaredNorm();
  EXPECT_NE(Llt<N>(indefinite).info(), Eigen::Success);
  EXPECT_FALSE(hinf::runtime::detail::SmallLlt<N>(indefinite).ok());
  const Eigen::Matrix<double, N, N> zero = Eigen::Matrix<double, N, N>::Zero();
  EXPECT_NE(Llt<N>(zero).info(), Eigen::Success);
  EXPECT_FALSE(hinf::runtime::detail::SmallLlt<N>(zero).ok());
}

TEST(SmallCholesky, SameFactorAndSolvesAsEigenBitForBit) {
  std::mt19937_64 rng(20261208);
  check_size<1, 1>(rng);
  check_size<2, 3>(rng);
  check_size<3, 6>(rng);   // S of the Hill EKFs: 3 x 3, K^T = S^-1 (H P) with H P 3 x 6
  check_size<3, 15>(rng);  // GPS/INS: 15 states
  check_size<4, 4>(rng);
  check_size<5, 2>(rng);
  check_size<6, 6>(rng);  // the REKF's gamma^2 I - L P L^T, two panels
  check_size<6, 1>(rng);
  check_size<7, 7>(rng);
  check_size<9, 5>(rng);  // three panels
}

TEST(SmallCholesky, DynamicSizesAreEigensOwn) {
  std::mt19937_64 rng(7);
  const Eigen::Matrix<double, 5, 5> S = random_spd<5>(rng, 1.0);
  const Eigen::MatrixXd Sd = S;
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(5, 3);
  const hinf::runtime::detail::SmallLlt<Eigen::Dynamic> small(Sd);
  ASSERT_TRUE(small.ok());
  const Eigen::MatrixXd x = small.solve<Eigen::Dynamic>(B), x_eigen = Eigen::LLT<Eigen::MatrixXd>(Sd).solve(B);
  EXPECT_TRUE(bitwise_equal(x, x_eigen));
}

// all_finite, the filters' per-step finiteness check: Eigen's allFinite verdict on finite
// entries (huge, tiny, ±0), on one NaN, +∞ or −∞ anywhere, and on an empty matrix.
TEST(Covariance, AllFiniteIsEigensVerdict) {
  const double special[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::max(),
                            -std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min(), -0.0};
  for (const double v : special)
    for (int i = 0; i < 36; i += 7) {
      Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Constant(1e300);
      M(i) = v;
      EXPECT_EQ(hinf::runtime::detail::all_finite(M), M.allFinite()) << v << " at " << i;
      const Eigen::Vector3d y(v, 2.0, -3.0);
      EXPECT_EQ(hinf::runtime::detail::all_finite(y), y.allFinite()) << v;
    }
  EXPECT_TRUE(hinf::runtime::detail::all_finite(Eigen::MatrixXd(0, 0)));
}

}  // namespace
