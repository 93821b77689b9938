// The synthesised robust H-infinity filter as a discrete LTI system, docs/maths.md (5)–(6):
//
//     z_F(k)   = C_F x_F(k)             [+ D_F y(k) for a filtered estimate, (140)]
//     x_F(k+1) = A_F x_F(k) + B_F y(k)  [+ G_F u(k) with a known input, (121)]
//
// Without D_F, z_F(k) depends on y(0..k-1) only: the filter is a one-step predictor; with
// D_F (the filtered observer of docs/maths.md §18.6, LtiFilter only) it also uses y(k).
// step(y(k)) returns z_F(k) and then advances the state, in that order.
//
// Two variants with the same semantics:
//   LtiFilter                    dimensions known at run time (e.g. from a gains file);
//                                all buffers are allocated at construction, step() does
//                                not allocate.
//   FixedLtiFilter<NX, NY, NZ>   dimensions fixed at compile time (flight code), no heap.
//
// Construction validates the gains (shapes, finiteness, Schur stability of A_F, i.e.
// spectral radius < 1) and throws std::invalid_argument naming the matrix and the
// offending dimensions or value. validate_lti_gains() is the non-throwing form.
// Needs Eigen only.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace hinf::runtime {

enum class LtiGainsError {
  None = 0,
  EmptyDimension,     // n, m or l is zero
  ShapeMismatch,      // A_F not n x n, B_F not n x m, C_F not l x n (or not the fixed size)
  NonFinite,          // a NaN or Inf entry
  NotSchurStable,     // spectral radius of A_F >= 1
};

inline const char* to_string(LtiGainsError e) {
  switch (e) {
    case LtiGainsError::None: return "ok";
    case LtiGainsError::EmptyDimension: return "empty dimension";
    case LtiGainsError::ShapeMismatch: return "shape mismatch";
    case LtiGainsError::NonFinite: return "non-finite entry";
    case LtiGainsError::NotSchurStable: return "A_F not Schur stable";
  }
  return "unknown";
}

struct LtiGainsValidation {
  LtiGainsError error = LtiGainsError::None;
  std::string message;  // empty when ok; otherwise names the matrix and dims/value
  double spectral_radius = std::numeric_limits<double>::quiet_NaN();  // of A_F, if computed
  bool ok() const { return error == LtiGainsError::None; }
};

namespace detail {

template <class Derived>
std::string dims(const Eigen::MatrixBase<Derived>& M) {
  return std::to_string(M.rows()) + "x" + std::to_string(M.cols());
}

template <class Derived>
bool first_non_finite(const Eigen::MatrixBase<Derived>& M, Eigen::Index& i, Eigen::Index& j) {
  for (Eigen::Index c = 0; c < M.cols(); ++c)
    for (Eigen::Index r = 0; r < M.rows(); ++r)
      if (!std::isfinite(static_cast<double>(M(r, c)))) {
        i = r;
        j = c;
        return true;
      }
  return false;
}

}  // namespace detail

// Non-throwing validation of (A_F, B_F, C_F). Expected sizes: A_F n x n, B_F n x m,
// C_F l x n, with n, m, l > 0. If expected_n/m/l >= 0 they are also enforced (fixed-size
// filters). Schur stability: spectral radius of A_F strictly below 1 (eigenvalues from
// Eigen::EigenSolver, computed once here).
template <class DA, class DB, class DC>
LtiGainsValidation validate_lti_gains(const Eigen::MatrixBase<DA>& A_F, const Eigen::MatrixBase<DB>& B_F,
                                      const Eigen::MatrixBase<DC>& C_F, Eigen::Index expected_n = -1,
                                      Eigen::Index expected_m = -1, Eigen::Index expected_l = -1) {
  LtiGainsValidation v;
  auto fail = [&](LtiGainsError e, const std::string& msg) {
    v.error = e;
    v.message = msg;
    return v;
  };
  const Eigen::Index n = A_F.rows(), m = B_F.cols(), l = C_F.rows();
  if (n == 0 || A_F.cols() == 0) return fail(LtiGainsError::EmptyDimension, "A_F is empty (" + detail::dims(A_F) + "); n must be > 0");
  if (m == 0) return fail(LtiGainsError::EmptyDimension, "B_F has no columns (" + detail::dims(B_F) + "); m must be > 0");
  if (l == 0) return fail(LtiGainsError::EmptyDimension, "C_F has no rows (" + detail::dims(C_F) + "); l must be > 0");
  if (A_F.cols() != n) return fail(LtiGainsError::ShapeMismatch, "A_F must be square (n x n); got " + detail::dims(A_F));
  if (B_F.rows() != n)
    return fail(LtiGainsError::ShapeMismatch, "B_F must be n x m with n = " + std::to_string(n) + " (rows of A_F); got " + detail::dims(B_F));
  if (C_F.cols() != n)
    return fail(LtiGainsError::ShapeMismatch, "C_F must be l x n with n = " + std::to_string(n) + " (rows of A_F); got " + detail::dims(C_F));
  if (expected_n >= 0 && n != expected_n)
    return fail(LtiGainsError::ShapeMismatch, "A_F must be " + std::to_string(expected_n) + "x" + std::to_string(expected_n) + " for this filter type; got " + detail::dims(A_F));
  if (expected_m >= 0 && m != expected_m)
    return fail(LtiGainsError::ShapeMismatch, "B_F must be " + std::to_string(n) + "x" + std::to_string(expected_m) + " for this filter type; got " + detail::dims(B_F));
  if (expected_l >= 0 && l != expected_l)
    return fail(LtiGainsError::ShapeMismatch, "C_F must be " + std::to_string(expected_l) + "x" + std::to_string(n) + " for this filter type; got " + detail::dims(C_F));
  Eigen::Index i = 0, j = 0;
  auto nonfinite = [&](const char* name, double value) {
    std::ostringstream os;
    os << name << " has a non-finite entry " << value << " at (" << i << ", " << j << ") (0-based)";
    return fail(LtiGainsError::NonFinite, os.str());
  };
  if (detail::first_non_finite(A_F, i, j)) return nonfinite("A_F", static_cast<double>(A_F(i, j)));
  if (detail::first_non_finite(B_F, i, j)) return nonfinite("B_F", static_cast<double>(B_F(i, j)));
  if (detail::first_non_finite(C_F, i, j)) return nonfinite("C_F", static_cast<double>(C_F(i, j)));

  const Eigen::MatrixXd A = A_F.template cast<double>();
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, /*computeEigenvectors=*/false);
  if (es.info() != Eigen::Success) return fail(LtiGainsError::NotSchurStable, "A_F: eigenvalue computation did not converge");
  Eigen::Index imax = 0;
  v.spectral_radius = es.eigenvalues().cwiseAbs().maxCoeff(&imax);
  if (!(v.spectral_radius < 1.0)) {
    std::ostringstream os;
    os.precision(10);
    const auto lam = es.eigenvalues()(imax);
    os << "A_F (" << n << "x" << n << ") is not Schur stable: spectral radius " << v.spectral_radius
       << " >= 1 (eigenvalue " << lam.real() << (lam.imag() < 0 ? " - " : " + ") << std::abs(lam.imag()) << "i)";
    v.error = LtiGainsError::NotSchurStable;
    v.message = os.str();
    return v;
  }
  return v;
}

namespace detail {
// Moore-Penrose pseudo-inverse by a complete orthogonal decomposition (rank-revealing,
// Eigen's default threshold). Computed once, at construction.
inline Eigen::MatrixXd pseudo_inverse(const Eigen::MatrixXd& C) {
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(C);
  return cod.pseudoInverse();
}
}  // namespace detail

// ---------------------------------------------------------------------------------------
// Dynamic-size filter.
class LtiFilter {
 public:
  using Matrix = Eigen::MatrixXd;
  using Vector = Eigen::VectorXd;

  // Throws std::invalid_argument (message from validate_lti_gains) on invalid gains.
  LtiFilter(const Eigen::Ref<const Matrix>& A_F, const Eigen::Ref<const Matrix>& B_F,
            const Eigen::Ref<const Matrix>& C_F)
      : LtiFilter(A_F, B_F, C_F, Matrix::Zero(A_F.rows(), 0)) {}

  // With a known input u (docs/maths.md (121)): x_F(k+1) = A_F x_F(k) + B_F y(k) + G_F u(k);
  // G_F is n x r (r = 0: none). Then step(y, u) must be used.
  LtiFilter(const Eigen::Ref<const Matrix>& A_F, const Eigen::Ref<const Matrix>& B_F,
            const Eigen::Ref<const Matrix>& C_F, const Eigen::Ref<const Matrix>& G_F)
      : LtiFilter(A_F, B_F, C_F, G_F, Matrix(0, 0)) {}

  // With the feedthrough of a filtered estimate (docs/maths.md (140)): z_F(k) = C_F x_F(k) +
  // D_F y(k); D_F is l x m, or 0 x 0 for none. G_F as above (n x 0: no known input).
  LtiFilter(const Eigen::Ref<const Matrix>& A_F, const Eigen::Ref<const Matrix>& B_F,
            const Eigen::Ref<const Matrix>& C_F, const Eigen::Ref<const Matrix>& G_F,
            const Eigen::Ref<const Matrix>& D_F) {
    LtiGainsValidation v = validate_lti_gains(A_F, B_F, C_F);
    if (!v.ok()) throw std::invalid_argument("hinf::runtime::LtiFilter: " + v.message);
    if (G_F.rows() != A_F.rows() || !G_F.allFinite())
      throw std::invalid_argument("hinf::runtime::LtiFilter: G_F must be n x r with finite entries, n = " +
                                  std::to_string(A_F.rows()) + "; got " + detail::dims(G_F));
    if (D_F.size() > 0 && (D_F.rows() != C_F.rows() || D_F.cols() != B_F.cols() || !D_F.allFinite()))
      throw std::invalid_argument("hinf::runtime::LtiFilter: D_F must be l x m with finite entries, l = " +
                                  std::to_string(C_F.rows()) + ", m = " + std::to_string(B_F.cols()) + "; got " +
                                  detail::dims(D_F));
    D_F_ = D_F.size() > 0 ? Matrix(D_F) : Matrix::Zero(C_F.rows(), B_F.cols());
    feedthrough_ = D_F.size() > 0;
    spectral_radius_ = v.spectral_radius;
    A_F_ = A_F;
    B_F_ = B_F;
    C_F_ = C_F;
    G_F_ = G_F;
    C_F_pinv_ = detail::pseudo_inverse(C_F_);
    x_F_ = Vector::Zero(n());
    x_next_ = Vector::Zero(n());
    z_F_ = Vector::Zero(l());
  }

  // Non-throwing check of gains before construction.
  static LtiGainsValidation validate(const Eigen::Ref<const Matrix>& A_F, const Eigen::Ref<const Matrix>& B_F,
                                     const Eigen::Ref<const Matrix>& C_F) {
    return validate_lti_gains(A_F, B_F, C_F);
  }

  Eigen::Index n() const { return A_F_.rows(); }  // filter order
  Eigen::Index m() const { return B_F_.cols(); }  // measurement size
  Eigen::Index l() const { return C_F_.rows(); }  // estimated-signal size
  Eigen::Index r() const { return G_F_.cols(); }  // known-input size (0: none)

  // x_F(0) = C_F^+ z0 (minimum-norm least-squares state reproducing the initial guess).
  void init(const Eigen::Ref<const Vector>& z0) {
    check_size("z0", z0.size(), l());
    x_F_.noalias() = C_F_pinv_ * z0;
  }
  // Set x_F directly (e.g. zero, or a state saved earlier).
  void set_state(const Eigen::Ref<const Vector>& x_F) {
    check_size("x_F", x_F.size(), n());
    x_F_ = x_F;
  }

  // One step of docs/maths.md (5)–(6): returns z_F(k) = C_F x_F(k) (+ D_F y(k)), then
  // x_F(k+1) = A_F x_F(k) + B_F y(k).
  // The returned reference stays valid until the next call. No heap allocation.
  // Throws std::invalid_argument only if y has the wrong size, or the filter has a known
  // input (r() > 0: use step(y, u)).
  const Vector& step(const Eigen::Ref<const Vector>& y) {
    if (r() > 0)
      throw std::invalid_argument("hinf::runtime::LtiFilter: this filter has a known input (r = " +
                                  std::to_string(r()) + "); call step(y, u)");
    return advance(y);
  }

  // The same with the known input u(k) (size r()): x_F(k+1) = A_F x_F + B_F y + G_F u.
  const Vector& step(const Eigen::Ref<const Vector>& y, const Eigen::Ref<const Vector>& u) {
    check_size("u", u.size(), r());
    const Vector& z = advance(y);
    x_F_.noalias() += G_F_ * u;
    return z;
  }

  // Current estimate z_F(k) = C_F x_F(k) without advancing (for the state after the last step;
  // for a filtered estimate this is its part without y(k), D_F y(k) is not added).
  const Vector& output() {
    z_F_.noalias() = C_F_ * x_F_;
    return z_F_;
  }

  const Vector& x_F() const { return x_F_; }
  const Matrix& A_F() const { return A_F_; }
  const Matrix& B_F() const { return B_F_; }
  const Matrix& C_F() const { return C_F_; }
  const Matrix& G_F() const { return G_F_; }
  const Matrix& D_F() const { return D_F_; }  // l x m, zero without a feedthrough
  const Matrix& C_F_pinv() const { return C_F_pinv_; }
  double spectral_radius() const { return spectral_radius_; }  // of A_F, from construction

 private:
  // z_F(k) = C_F x_F(k) (+ D_F y(k)), then x_F(k+1) = A_F x_F(k) + B_F y(k).
  const Vector& advance(const Eigen::Ref<const Vector>& y) {
    check_size("y", y.size(), m());
    z_F_.noalias() = C_F_ * x_F_;
    if (feedthrough_) z_F_.noalias() += D_F_ * y;
    x_next_.noalias() = A_F_ * x_F_;
    x_next_.noalias() += B_F_ * y;
    x_F_.swap(x_next_);
    return z_F_;
  }

  static void check_size(const char* what, Eigen::Index got, Eigen::Index want) {
    if (got != want)
      throw std::invalid_argument(std::string("hinf::runtime::LtiFilter: ") + what + " has size " +
                                  std::to_string(got) + ", expected " + std::to_string(want));
  }

  Matrix A_F_, B_F_, C_F_, G_F_, D_F_, C_F_pinv_;
  Vector x_F_, x_next_, z_F_;
  bool feedthrough_ = false;
  double spectral_radius_ = 0.0;
};

// ---------------------------------------------------------------------------------------
// Fixed-size filter: NX = filter order n, NY = measurement size m, NZ = output size l.
// The predictor (5)–(6) only: no known input, no feedthrough (use LtiFilter for those).
template <int NX, int NY, int NZ, class Scalar = double>
class FixedLtiFilter {
  static_assert(NX > 0 && NY > 0 && NZ > 0, "FixedLtiFilter: dimensions must be positive");

 public:
  static constexpr int n = NX, m = NY, l = NZ;
  using StateMatrix = Eigen::Matrix<Scalar, NX, NX>;
  using InputMatrix = Eigen::Matrix<Scalar, NX, NY>;
  using OutputMatrix = Eigen::Matrix<Scalar, NZ, NX>;
  using PinvMatrix = Eigen::Matrix<Scalar, NX, NZ>;
  using State = Eigen::Matrix<Scalar, NX, 1>;
  using Measurement = Eigen::Matrix<Scalar, NY, 1>;
  using Output = Eigen::Matrix<Scalar, NZ, 1>;
  using DynMatrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

  // Accepts fixed or dynamic matrices (e.g. from a gains file); shapes are checked
  // against NX, NY, NZ. Throws std::invalid_argument on invalid gains.
  FixedLtiFilter(const Eigen::Ref<const DynMatrix>& A_F, const Eigen::Ref<const DynMatrix>& B_F,
                 const Eigen::Ref<const DynMatrix>& C_F) {
    LtiGainsValidation v = validate_lti_gains(A_F, B_F, C_F, NX, NY, NZ);
    if (!v.ok()) throw std::invalid_argument("hinf::runtime::FixedLtiFilter: " + v.message);
    spectral_radius_ = v.spectral_radius;
    A_F_ = A_F;
    B_F_ = B_F;
    C_F_ = C_F;
    C_F_pinv_ = detail::pseudo_inverse(C_F_.template cast<double>()).template cast<Scalar>();
    x_F_.setZero();
    z_F_.setZero();
  }

  static LtiGainsValidation validate(const Eigen::Ref<const DynMatrix>& A_F, const Eigen::Ref<const DynMatrix>& B_F,
                                     const Eigen::Ref<const DynMatrix>& C_F) {
    return validate_lti_gains(A_F, B_F, C_F, NX, NY, NZ);
  }

  // x_F(0) = C_F^+ z0.
  void init(const Output& z0) { x_F_.noalias() = C_F_pinv_ * z0; }
  void set_state(const State& x_F) { x_F_ = x_F; }

  // One step of docs/maths.md (5)–(6): returns z_F(k), then advances x_F. No heap allocation.
  const Output& step(const Measurement& y) {
    z_F_.noalias() = C_F_ * x_F_;
    State x_next;
    x_next.noalias() = A_F_ * x_F_;
    x_next.noalias() += B_F_ * y;
    x_F_ = x_next;
    return z_F_;
  }

  const Output& output() {
    z_F_.noalias() = C_F_ * x_F_;
    return z_F_;
  }

  const State& x_F() const { return x_F_; }
  const StateMatrix& A_F() const { return A_F_; }
  const InputMatrix& B_F() const { return B_F_; }
  const OutputMatrix& C_F() const { return C_F_; }
  const PinvMatrix& C_F_pinv() const { return C_F_pinv_; }
  double spectral_radius() const { return spectral_radius_; }

 private:
  StateMatrix A_F_;
  InputMatrix B_F_;
  OutputMatrix C_F_;
  PinvMatrix C_F_pinv_;
  State x_F_;
  Output z_F_;
  double spectral_radius_ = 0.0;
};

}  // namespace hinf::runtime
