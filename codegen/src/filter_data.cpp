// Maths for code generation: rounding, pseudo-inverse, test vectors, error bound.
#include "filter_data.hpp"

#include <cfloat>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hinf/common/error.hpp"

namespace hinf::codegen::detail {
namespace {

using Real = CodegenOptions::Real;
using MatL = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
using VecL = Eigen::Matrix<long double, Eigen::Dynamic, 1>;

double unit_roundoff(Real real) {
  return real == Real::Float ? std::ldexp(1.0, -24) : std::ldexp(1.0, -53);
}

// Rounds to the target type; reports overflow naming the matrix and entry.
Eigen::MatrixXd round_to(const Eigen::MatrixXd& m, Real real, const char* name) {
  if (real == Real::Double) return m;
  Eigen::MatrixXd r(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      const auto f = static_cast<float>(m(i, j));
      if (!std::isfinite(f))
        throw Error(ErrorCode::InvalidInput,
                    std::string(name) + "(" + std::to_string(i) + "," + std::to_string(j) +
                        ") = " + std::to_string(m(i, j)) +
                        " does not fit in float (largest float is 3.4e38); use --real double");
      r(i, j) = static_cast<double>(f);
    }
  return r;
}

struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform on [-1, 1), exactly representable in double (53-bit grid).
  double uniform() { return std::ldexp(static_cast<double>(next() >> 11), -52) - 1.0; }
};

long double gamma_k(long double k, long double u) { return k * u / (1.0L - k * u); }

// Running error bound of init + `steps` steps of docs/maths.md (5)–(6) evaluated in arithmetic
// with unit roundoff u, given the exact states x (column k = x(k)). With δ_j the
// rounding error committed in step j, the state error is exactly
//   e(k) = A^k e(0) + Σ_{j<k} A^(k-1-j) δ_j,
// so |e(k)| ≤ |A^k| |e(0)| + Σ_{j<k} |A^(k-1-j)| |δ_j| componentwise, with
// |e(0)| ≤ γ_l |pinv| |z0| and |δ_j| ≤ γ_{n+m+r} (|A| |x̂_j| + |B| |y_j| + |G| |u_j|) (G, u:
// the known input of (121), r = 0 without). Using the powers of the (stable) A rather than
// powers of |A| keeps the bound realistic.
// Returns, per step and output, a bound on |computed z(k) − exact z(k)|:
//   |C e(k)| + γ_n |C| |x̂_k|  with |C e(k)| bounded through |C A^i|.
// With a feedthrough D (a filtered estimate, (140)) the output's own rounding is
// γ_{n+m} (|C| |x̂_k| + |D| |y_k|) instead of γ_n |C| |x̂_k|.
struct RecursionData {
  const MatL &A, &B, &C, &G, &P;
  const MatL* D;  // nullptr without a feedthrough
};
MatL running_bound(const RecursionData& s, const VecL& z0, const MatL& Y, const MatL& U, const MatL& X,
                   long double u) {
  const Eigen::Index steps = Y.rows();
  const auto n = static_cast<long double>(s.A.rows());
  const auto m = static_cast<long double>(s.B.cols());
  const auto r = static_cast<long double>(s.G.cols());
  const auto l = static_cast<long double>(s.C.rows());
  // |A^i| and |C A^i|, i = 0..steps-1.
  std::vector<MatL> abs_pow, abs_cpow;
  MatL power = MatL::Identity(s.A.rows(), s.A.cols());
  for (Eigen::Index i = 0; i < steps; ++i) {
    abs_pow.push_back(power.cwiseAbs());
    abs_cpow.push_back((s.C * power).cwiseAbs());
    power = s.A * power;
  }
  const MatL Aa = s.A.cwiseAbs(), Ba = s.B.cwiseAbs(), Ca = s.C.cwiseAbs(), Ga = s.G.cwiseAbs();
  const VecL e0 = gamma_k(l, u) * (s.P.cwiseAbs() * z0.cwiseAbs());
  std::vector<VecL> delta;  // bounds on |δ_j|
  MatL bound(steps, s.C.rows());
  for (Eigen::Index k = 0; k < steps; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    VecL e = abs_pow[ku] * e0;          // bound on |e(k)|
    VecL ce = abs_cpow[ku] * e0;        // bound on |C e(k)|
    for (std::size_t j = 0; j < ku; ++j) {
      e += abs_pow[ku - 1 - j] * delta[j];
      ce += abs_cpow[ku - 1 - j] * delta[j];
    }
    const VecL xa = X.col(k).cwiseAbs() + e;  // bound on |computed x(k)|
    const VecL ya = Y.row(k).transpose().cwiseAbs();
    const VecL output =
        s.D ? VecL(gamma_k(n + m, u) * (Ca * xa + s.D->cwiseAbs() * ya)) : VecL(gamma_k(n, u) * (Ca * xa));
    bound.row(k) = (ce + output).transpose();
    VecL step = Aa * xa + Ba * ya;
    if (r > 0) step += Ga * U.row(k).transpose().cwiseAbs();
    delta.push_back(gamma_k(n + m + r, u) * step);
  }
  return bound;
}

}  // namespace

FilterData make_filter_data(const runtime_yaml::GainsFile& gains, Real real) {
  FilterData d;
  d.A_F = round_to(gains.A_F, real, "filter.A_F");
  d.B_F = round_to(gains.B_F, real, "filter.B_F");
  d.C_F = round_to(gains.C_F, real, "filter.C_F");
  d.feedthrough = gains.filtered;
  d.D_F = d.feedthrough ? round_to(gains.D_F, real, "filter.D_F") : Eigen::MatrixXd::Zero(d.C_F.rows(), d.B_F.cols());
  d.G_F = gains.G_F.cols() > 0 ? round_to(gains.G_F, real, "filter.G_F") : Eigen::MatrixXd::Zero(d.A_F.rows(), 0);
  // Pseudo-inverse of the C_F that is emitted (after rounding), computed in double.
  const Eigen::MatrixXd pinv = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(d.C_F)
                                   .pseudoInverse();
  if (!pinv.allFinite())
    throw Error(ErrorCode::NumericalFailure, "pseudo-inverse of filter.C_F is not finite");
  d.C_F_pinv = round_to(pinv, real, "pinv(filter.C_F)");
  return d;
}

TestVectors make_test_vectors(const FilterData& data, Real real, int steps, std::uint64_t seed) {
  if (steps < 1) throw Error(ErrorCode::InvalidInput, "test-vector length must be at least 1");
  const Eigen::Index m = data.B_F.cols(), l = data.C_F.rows(), n = data.A_F.rows(), r = data.G_F.cols();
  const auto rnd = [real](double v) {
    return real == Real::Float ? static_cast<double>(static_cast<float>(v)) : v;
  };
  SplitMix64 rng{seed};
  TestVectors tv;
  tv.z0.resize(l);
  for (Eigen::Index i = 0; i < l; ++i) tv.z0(i) = rnd(rng.uniform());
  tv.y.resize(steps, m);
  for (Eigen::Index k = 0; k < steps; ++k)
    for (Eigen::Index j = 0; j < m; ++j) tv.y(k, j) = rnd(rng.uniform());
  tv.u.resize(steps, r);
  for (Eigen::Index k = 0; k < steps; ++k)
    for (Eigen::Index j = 0; j < r; ++j) tv.u(k, j) = rnd(rng.uniform());

  const MatL A = data.A_F.cast<long double>(), B = data.B_F.cast<long double>(),
             C = data.C_F.cast<long double>(), D = data.D_F.cast<long double>(),
             G = data.G_F.cast<long double>(), P = data.C_F_pinv.cast<long double>();
  const VecL z0 = tv.z0.cast<long double>();
  const MatL Y = tv.y.cast<long double>(), U = tv.u.cast<long double>();
  MatL X(n, steps);
  MatL Z(steps, l);
  VecL x = P * z0;
  for (Eigen::Index k = 0; k < steps; ++k) {
    X.col(k) = x;
    Z.row(k) = (C * x + D * Y.row(k).transpose()).transpose();
    x = A * x + B * Y.row(k).transpose();
    if (r > 0) x += G * U.row(k).transpose();
  }

  const long double max_value = real == Real::Float ? FLT_MAX : DBL_MAX;
  if (!Z.allFinite() || Z.cwiseAbs().maxCoeff() > max_value / 4)
    throw Error(ErrorCode::NumericalFailure,
                "the test vectors overflow over " + std::to_string(steps) +
                    " steps: the filter is violently unstable (check its spectral radius); "
                    "use fewer --vector-steps");
  tv.z.resize(steps, l);
  for (Eigen::Index k = 0; k < steps; ++k)
    for (Eigen::Index i = 0; i < l; ++i) tv.z(k, i) = rnd(static_cast<double>(Z(k, i)));

  const long double u = unit_roundoff(real);
  const long double u_ref = std::numeric_limits<long double>::epsilon() / 2;
  const RecursionData recursion{A, B, C, G, P, data.feedthrough ? &D : nullptr};
  const MatL bound = running_bound(recursion, z0, Y, U, X, u) + running_bound(recursion, z0, Y, U, X, u_ref) +
                     u * Z.cwiseAbs();  // the expected values are stored rounded
  // The driver's subtraction |z − z_expected| is itself rounded (relative u).
  const long double tol = bound.maxCoeff() * (1.0L + 4.0L * u);
  // Store the tolerance rounded up so that rounding never tightens it.
  double t = static_cast<double>(tol);
  if (static_cast<long double>(t) < tol) t = std::nextafter(t, DBL_MAX);
  if (real == Real::Float) {
    float f = static_cast<float>(t);
    if (static_cast<double>(f) < t) f = std::nextafter(f, FLT_MAX);
    t = static_cast<double>(f);
  }
  tv.tolerance = t;
  return tv;
}

}  // namespace hinf::codegen::detail
