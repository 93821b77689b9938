// The verified bracket of docs/maths.md §5.9, eqs. (113)–(117).
#include "hinf/sdp/dual_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace hinf::sdp {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// Unit round-off of double and the classical bound γ_k = k·u/(1 − k·u) on the relative error
// of a k-term sum of products (Higham, Accuracy and Stability, §3.1).
constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;
using LongMatrix = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
double gamma_k(double k) { return k * kUnitRoundoff / (1 - k * kUnitRoundoff); }
// The same for sums accumulated in long double (x87 extended on x86-64: 2^-64; where long
// double is double, this is u again).
constexpr double kLongUnitRoundoff = static_cast<double>(std::numeric_limits<long double>::epsilon() / 2);
double gamma_long(double k) { return k * kLongUnitRoundoff / (1 - k * kLongUnitRoundoff); }
// A computed symmetric eigenvalue is within this many N·u·‖A‖_F of an exact eigenvalue of
// A (backward stability of Householder tridiagonalisation and implicit QR; the constant
// is generous: the proven bound is a modest multiple of N·u·‖A‖₂ ≤ N·u·‖A‖_F).
constexpr double kEigenErrorFactor = 8.0;
// Rounds (at most) of the Z-metric projection of §5.9 that drive the equality residual to
// round-off: one or two where the point is well centred, more when damped.
constexpr int kProjectionRounds = 40;
// A projection step is damped to ‖αU‖₂ ≤ this (a full step where the point is well centred).
constexpr double kMaxStep = 0.9;
// Interior shifts η of the dual point, Z₀ + η·diag(Z₀), tried in turn: near the optimum
// the central Z₀ is nearly singular (complementarity; λ_min of its Jacobi scaling ~1e-12
// measured on random n = 4 plants), below what the residual correction can be bounded
// by, so it is moved inside the cone by η (relative, in the Jacobi scaling) at a cost of
// about η·N relative in the bound.
constexpr double kInteriorShifts[] = {1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6};
// Projection metrics built beyond the first (one QR of an N(N+1)/2 × p matrix each, the
// dominant cost at large n) when the first does not verify.
constexpr int kFreshMetrics = 6;
// Weights θ of an earlier path point's dual in (1 − θ)·Z_final + θ·Z_earlier, tried in
// turn, and how many earlier centred points are tried (one QR each).
constexpr double kInteriorWeights[] = {1e-12, 1e-10, 1e-8, 1e-6, 1e-4, 1e-2};
constexpr int kPathCandidates = 4;

// A ≻ shift·I, verified by a floating-point Cholesky factorisation (Rump, "Verification of
// positive definiteness", BIT 46, 2006, Thm. 2.3): if fl-Cholesky of A − (c + shift)·I
// succeeds with c = γ_{n+1}/(1 − γ_{n+1})·tr(A) + 4n(2(n+2) + max Aᵢᵢ)·η (η the smallest
// subnormal), then A − shift·I is positive definite. A should be Jacobi-scaled. The
// factorisation runs in long double (A converts exactly; u = 2^-64 on x86-64), so that c
// is ~2000× below λ_min of the nearly singular dual points near the optimum (λ_min(Z)
// ~1e-14 relative at paper δ̄ = 1, where double's c ≈ N²·u ≈ 4e-13 cannot verify them).
bool verified_positive_definite(const MatrixXd& A, double shift) {
  constexpr long double u = std::numeric_limits<long double>::epsilon() / 2;
  const long double n = static_cast<long double>(A.rows());
  const long double g = (n + 1) * u / (1 - (n + 1) * u);
  LongMatrix B = A.cast<long double>();
  const long double c = g / (1 - g) * B.trace() * (1 + 4 * n * u) +
                        4 * n * (2 * (n + 2) + B.diagonal().maxCoeff()) * std::numeric_limits<long double>::denorm_min();
  B.diagonal().array() -= (c + static_cast<long double>(shift)) * (1 + 4 * u);
  return Eigen::LLT<LongMatrix>(B).info() == Eigen::Success;
}

double eigen_error(const MatrixXd& A) { return kEigenErrorFactor * A.rows() * kUnitRoundoff * A.norm(); }

// The powers of two nearest √diagᵢ (1 where diagᵢ ≤ 0): an exact Jacobi scaling.
VectorXd jacobi_scaling(const VectorXd& diag) {
  VectorXd d(diag.size());
  for (int i = 0; i < diag.size(); ++i)
    d(i) = diag(i) > 0 ? std::ldexp(1.0, static_cast<int>(std::lround(0.5 * std::log2(diag(i))))) : 1.0;
  return d;
}

// The Mᵢ, entry by entry (upper triangle), grouped by position for the Gram matrix.
struct SparseBasis {
  std::vector<lmi::SparseEntry> entries;  // sorted by (row, col)
  std::vector<int> terms;                 // number of entries of each Mᵢ
};

SparseBasis sparse_basis(const lmi::LmiProblem& lmi) {
  SparseBasis b;
  b.entries = lmi.sparse_entries();
  std::sort(b.entries.begin(), b.entries.end(), [](const lmi::SparseEntry& a, const lmi::SparseEntry& e) {
    return a.row != e.row ? a.row < e.row : a.col != e.col ? a.col < e.col : a.param < e.param;
  });
  b.terms.assign(lmi.num_params(), 0);
  for (const auto& e : b.entries) ++b.terms[e.param];
  return b;
}

// tr(Y Mᵢ) = Σ mult·v·Y(r, c) over the entries of Mᵢ (mult 2 off the diagonal).
double multiplicity(const lmi::SparseEntry& e) { return e.row == e.col ? 1.0 : 2.0; }

// cᵢ + tr(Z Mᵢ) for every i, summed in long double, and with `bound` an upper bound on its
// modulus: plus γ_{k+1}·Σ|terms| for the rounding of the products and the k-term sum
// (eq. (114)).
VectorXd residual(const SparseBasis& b, const VectorXd& c, const MatrixXd& Z, bool bound) {
  const int p = static_cast<int>(c.size());
  std::vector<long double> sum(p), abs_sum(p);
  for (int i = 0; i < p; ++i) sum[i] = c(i), abs_sum[i] = std::abs(c(i));
  for (const auto& e : b.entries) {
    const long double t = static_cast<long double>(multiplicity(e) * e.value) * Z(e.row, e.col);
    sum[e.param] += t;
    abs_sum[e.param] += std::abs(t);
  }
  VectorXd r(p);
  for (int i = 0; i < p; ++i)
    r(i) = bound ? static_cast<double>(std::abs(sum[i]) + gamma_long(b.terms[i] + 2) * abs_sum[i]) * (1 + 2 * kUnitRoundoff)
                 : static_cast<double>(sum[i]);
  return r;
}

// G = [tr(Mᵢ Mⱼ)] (docs/maths.md (115)), from the entries that share a position.
MatrixXd gram_matrix(const SparseBasis& b, int p) {
  MatrixXd G = MatrixXd::Zero(p, p);
  std::size_t k = 0;
  while (k < b.entries.size()) {
    std::size_t end = k;
    while (end < b.entries.size() && b.entries[end].row == b.entries[k].row && b.entries[end].col == b.entries[k].col)
      ++end;
    const double mult = multiplicity(b.entries[k]);
    for (std::size_t a = k; a < end; ++a)
      for (std::size_t e = k; e < end; ++e)
        G(b.entries[a].param, b.entries[e].param) += mult * b.entries[a].value * b.entries[e].value;
    k = end;
  }
  return G;
}

// The Gram matrix with unit diagonal, Gs = Dg⁻¹ G Dg⁻¹, Dg = diag(‖Mᵢ‖_F) (column scaling of
// 𝒜), and a verified lower bound on σ_min(𝒜 Dg⁻¹) = √λ_min(Gs) (0 if none): the computed
// eigenvalue less its error and the rounding of G's entries.
double scaled_min_singular_value_bound(const SparseBasis& b, int p, VectorXd& column_norms) {
  const MatrixXd G = gram_matrix(b, p);
  column_norms = G.diagonal().cwiseSqrt();
  if (!(column_norms.minCoeff() > 0)) return 0.0;
  const MatrixXd Gs = column_norms.cwiseInverse().asDiagonal() * G * column_norms.cwiseInverse().asDiagonal();
  const double lmin = Eigen::SelfAdjointEigenSolver<MatrixXd>(Gs, Eigen::EigenvaluesOnly).eigenvalues()(0);
  const int max_share = *std::max_element(b.terms.begin(), b.terms.end());
  const double lo = lmin - eigen_error(Gs) - gamma_k(max_share + 4) * Gs.cwiseAbs().norm();
  return lo > 0 ? std::sqrt(lo) : 0.0;
}

// Z₀ = τ·(−M(x) − εI)⁻¹ with τ fitting the cost (docs/maths.md §5.9).
bool central_dual_point(const lmi::LmiProblem& lmi, const VectorXd& c, const VectorXd& x, double margin, MatrixXd& Z,
                        std::string& why) {
  const int N = lmi.order();
  MatrixXd slack = -lmi.evaluate(x);
  slack.diagonal().array() -= margin;
  const Eigen::LLT<MatrixXd> llt(slack);
  if (llt.info() != Eigen::Success) {
    why = "the primal point is not strictly feasible";
    return false;
  }
  MatrixXd W = llt.solve(MatrixXd::Identity(N, N));
  W = 0.5 * (W + W.transpose()).eval();
  VectorXd a;
  lmi.trace_products(W, a);
  const double tau = -c.dot(a) / a.squaredNorm();
  if (!(tau > 0)) {
    why = "the slack's inverse does not fit the cost (τ ≤ 0)";
    return false;
  }
  Z = tau * W;
  return true;
}

// The symmetric matrix whose svec (LmiProblem::scaled_jacobian's order: the lower triangle
// column by column, off-diagonal entries ×√2) is u.
MatrixXd smat(const VectorXd& u, int N) {
  MatrixXd U(N, N);
  const double s2 = std::sqrt(2.0);
  int k = 0;
  for (int c = 0; c < N; ++c) {
    U(c, c) = u(k++);
    for (int r = c + 1; r < N; ++r) U(r, c) = U(c, r) = u(k++) / s2;
  }
  return U;
}

// The Z-metric of §5.9 at a reference dual point Z_ref = LLᵀ: the QR factorisation of
// G = [svec LᵀMᵢL] (LmiProblem::scaled_jacobian with T = Lᵀ), whose condition number is the
// square root of that of [tr(Z Mᵢ Z Mⱼ)]. Built once (O(N²p²)) and reused by every
// projection of the candidates derived from Z_ref.
struct ProjectionMetric {
  bool ok = false;
  MatrixXd L;
  Eigen::HouseholderQR<MatrixXd> qr;
};

ProjectionMetric projection_metric(const lmi::LmiProblem& lmi, const MatrixXd& Z_ref) {
  ProjectionMetric m;
  const Eigen::LLT<MatrixXd> llt(Z_ref);
  if (llt.info() != Eigen::Success) return m;
  m.L = llt.matrixL();
  MatrixXd G(lmi::LmiProblem::scaled_jacobian_rows(lmi.order(), 0), lmi.num_params());
  lmi.scaled_jacobian(m.L.transpose(), G);
  m.qr.compute(G);
  m.ok = true;
  return m;
}

// One projection: Z ← Z − α·L·U·Lᵀ with U the least-norm solution of ⟨LᵀMᵢL, U⟩ = rᵢ =
// cᵢ + tr(Z Mᵢ) (the residual summed in long double), so that 𝒜*(L U Lᵀ) = r; α ≤ 1 keeps
// ‖αU‖₂ ≤ kMaxStep, so Z stays ≻ 0 near Z_ref. False (Z unchanged) if the step does not
// lower the residual or leaves the cone.
bool project(const lmi::LmiProblem& lmi, const SparseBasis& b, const VectorXd& c, const ProjectionMetric& m,
             MatrixXd& Z) {
  if (!m.ok) return false;
  const int N = lmi.order(), p = lmi.num_params();
  const VectorXd r = residual(b, c, Z, false);
  VectorXd w = VectorXd::Zero(m.qr.rows());
  w.head(p) = m.qr.matrixQR().topLeftCorner(p, p).triangularView<Eigen::Upper>().transpose().solve(r);
  const VectorXd u = m.qr.householderQ() * w;
  if (!u.allFinite()) return false;
  const MatrixXd U = smat(u, N);
  const double norm_U = Eigen::SelfAdjointEigenSolver<MatrixXd>(U, Eigen::EigenvaluesOnly).eigenvalues().cwiseAbs().maxCoeff();
  const double alpha = std::min(1.0, kMaxStep / norm_U);
  MatrixXd Zn = Z - alpha * (m.L * U * m.L.transpose());
  Zn = 0.5 * (Zn + Zn.transpose()).eval();
  if (Eigen::LLT<MatrixXd>(Zn).info() != Eigen::Success) return false;
  if (!(residual(b, c, Zn, false).norm() < r.norm())) return false;
  Z = Zn;
  return true;
}

// Σ Y∘M₀ in long double, less γ_{N²+1}·Σ|Y||M₀| (a lower bound on the exact tr(Y M₀)).
double trace_lower_bound(const MatrixXd& Y, const MatrixXd& M0, double& value) {
  long double s = 0, a = 0;
  for (int j = 0; j < Y.cols(); ++j)
    for (int i = 0; i < Y.rows(); ++i) {
      const long double t = static_cast<long double>(Y(i, j)) * M0(i, j);
      s += t;
      a += std::abs(t);
    }
  value = static_cast<double>(s);
  const double lo = static_cast<double>(s - gamma_long(static_cast<double>(Y.size()) + 1) * a);
  return lo - 2 * kUnitRoundoff * std::abs(lo);  // the rounding to double, either sign
}

// out += Σᵢ |xᵢ|·|entries of i| (both triangles).
void add_abs(const std::vector<lmi::SparseEntry>& entries, const VectorXd& x, MatrixXd& out) {
  for (const auto& e : entries) {
    const double t = std::abs(e.value * x(e.param));
    out(e.row, e.col) += t;
    if (e.row != e.col) out(e.col, e.row) += t;
  }
}

// −J·M·J ≻ (rounding of evaluating M(x), bounded through |M₀| + Σ|xᵢ||Mᵢ| = `abs_sum`,
// plus the data error)·I, all under the same exact congruence J (diagonal, powers of two),
// verified by Cholesky: then M(x) ≺ 0.
bool negative_definite_under(const VectorXd& j, const MatrixXd& M, const MatrixXd& abs_sum, const MatrixXd& data,
                             double rounding, double data_rounding) {
  const auto J = j.asDiagonal();
  const MatrixXd Ms = J * M * J;
  return verified_positive_definite(-Ms, rounding * (J * abs_sum * J).norm() + data_rounding * (J * data * J).norm());
}

// M(x) from the sparse basis, summed in long double and rounded to double once, with a
// bound on its error: |M̂ − M(x)| ≤ rounding·abs_sum entrywise (abs_sum = |M₀| + Σ|xᵢ||Mᵢ|).
// In double, evaluating through the factored terms, the bound (~p·u·‖abs_sum‖) exceeded the
// margin ε = 1e-12 at random n = 16 and could not verify M(x) ≺ 0.
struct EvaluatedLmi {
  MatrixXd M, abs_sum;
  double rounding = 0;
};

EvaluatedLmi evaluate_accurately(const lmi::LmiProblem& lmi, const SparseBasis& b, const VectorXd& x) {
  const int N = lmi.order();
  LongMatrix sum = lmi.constant().cast<long double>(), mag = sum.cwiseAbs();
  Eigen::MatrixXi count = Eigen::MatrixXi::Ones(N, N);
  for (const auto& e : b.entries) {
    const long double t = static_cast<long double>(e.value) * x(e.param);
    sum(e.row, e.col) += t;
    mag(e.row, e.col) += std::abs(t);
    ++count(e.row, e.col);
    if (e.row != e.col) {
      sum(e.col, e.row) += t;
      mag(e.col, e.row) += std::abs(t);
      ++count(e.col, e.row);
    }
  }
  EvaluatedLmi out;
  out.M = sum.cast<double>();
  out.abs_sum = mag.cast<double>();
  // a k-term sum of products in long double, then one rounding to double (and abs_sum's own)
  out.rounding = gamma_long(count.maxCoeff() + 1) + 3 * kUnitRoundoff;
  return out;
}

// M(x) ≺ 0 verified as is or under the Jacobi congruence J = diag(2^−round(log₂√|Mᵢᵢ|))
// (which judges a graded M by its relative eigenvalues): then p* ≤ cᵀx.
bool verify_upper(const lmi::LmiProblem& lmi, const SparseBasis& b, const VectorXd& x,
                  const std::vector<lmi::SparseEntry>& basis_error) {
  const EvaluatedLmi e = evaluate_accurately(lmi, b, x);
  MatrixXd data = MatrixXd::Zero(e.M.rows(), e.M.cols());
  add_abs(basis_error, x, data);
  const double data_rounding = 1 + gamma_k(static_cast<double>(basis_error.size()) + 2);
  if (negative_definite_under(VectorXd::Ones(e.M.rows()), e.M, e.abs_sum, data, e.rounding, data_rounding))
    return true;
  return negative_definite_under(jacobi_scaling(-e.M.diagonal()).cwiseInverse(), e.M, e.abs_sum, data, e.rounding,
                                 data_rounding);
}

// What the correction of (115) needs of the Jacobi scaling D (powers of two nearest
// √diag(Z₀)): σ ≤ σ_min of the column-normalised operator of the D Mᵢ D, less the data error.
struct ScaledOperator {
  VectorXd d, column_norms;
  double sigma = 0;
};

ScaledOperator scaled_operator(const lmi::LmiProblem& lmi, const SparseBasis& basis, const VectorXd& diag,
                               const std::vector<lmi::SparseEntry>& basis_error) {
  ScaledOperator op;
  op.d = jacobi_scaling(diag);
  SparseBasis scaled = basis;
  for (auto& e : scaled.entries) e.value *= op.d(e.row) * op.d(e.col);
  const double sigma0 = scaled_min_singular_value_bound(scaled, lmi.num_params(), op.column_norms);
  // σ_min of the perturbed operator ≥ σ₀ − ‖(‖D δMᵢ D‖_F/‖D Mᵢ D‖_F)ᵢ‖ (Cauchy–Schwarz over i)
  VectorXd delta2 = VectorXd::Zero(lmi.num_params());
  for (const auto& e : basis_error) {
    const double v = e.value * op.d(e.row) * op.d(e.col);
    delta2(e.param) += multiplicity(e) * v * v;
  }
  op.sigma = sigma0 - delta2.cwiseSqrt().cwiseQuotient(op.column_norms).norm() * (1 + 8 * kUnitRoundoff);
  return op;
}

// (114)–(117) for one candidate Z; true and out's bound filled if every step is verified.
bool verify_dual(const lmi::LmiProblem& lmi, const SparseBasis& basis, const VectorXd& c, const MatrixXd& Z,
                 const std::vector<lmi::SparseEntry>& basis_error, const ScaledOperator& op, DualBound& out) {
  // (114): the residual of the dual equalities, rounding and the data error included
  VectorXd r = residual(basis, c, Z, true);
  for (const auto& e : basis_error)  // |tr(Z δMᵢ)| ≤ Σ mult·|Z|∘bound
    r(e.param) += multiplicity(e) * std::abs(e.value * Z(e.row, e.col)) *
                  (1 + gamma_k(static_cast<double>(basis_error.size()) + 2));
  out.residual_bound = r.norm() * (1 + 2 * kUnitRoundoff);
  // (115)–(116) in the Jacobi scaling Z = D Zs D: Δ = D Δs D with Δs = 𝒜̃(G̃⁻¹r), 𝒜̃ the
  // operator of the D Mᵢ D, satisfies 𝒜*(Δ) = r, ‖Δs‖_F² = rᵀG̃⁻¹r ≤ ‖Dg⁻¹r‖²/σ², and
  // Z − Δ ⪰ 0 if λ_min(Zs) > ‖Δs‖_F
  out.correction_bound = r.cwiseQuotient(op.column_norms).norm() / op.sigma * (1 + 8 * kUnitRoundoff);
  // The test in Z's own Jacobi scaling E (powers of two): E⁻¹(Z − Δ)E⁻¹ ⪰ 0 if
  // λ_min(E⁻¹ZE⁻¹) > ‖E⁻¹DΔsDE⁻¹‖₂ ≤ max(dᵢ/eᵢ)²·‖Δs‖_F
  const VectorXd e = jacobi_scaling(Z.diagonal());
  const double ratio = op.d.cwiseQuotient(e).maxCoeff();
  const auto Einv = e.cwiseInverse().asDiagonal();
  const MatrixXd Zs = Einv * Z * Einv;
  const double threshold = ratio * ratio * out.correction_bound;
  if (!verified_positive_definite(Zs, threshold)) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "the dual point is not verifiably positive semidefinite (λ_min of the scaled Z not verified above "
                  "the correction %.3g)",
                  threshold);
    out.detail = buf;
    return false;
  }
  // (117): p* ≥ tr((Z − Δ) M₀) ≥ tr(Z M₀) − ‖Δs‖_F·‖D M₀ D‖_F
  const double trace_lo = trace_lower_bound(Z, lmi.constant(), out.dual_objective);
  const MatrixXd M0s = op.d.asDiagonal() * lmi.constant() * op.d.asDiagonal();
  out.lower_bound = trace_lo - out.correction_bound * M0s.norm() * (1 + 4 * kUnitRoundoff);
  if (!std::isfinite(out.lower_bound)) {
    out.detail = "the dual objective is not finite";
    return false;
  }
  return true;
}


// Projections of Z until the bound verifies (true, out filled) or they stop lowering the
// residual. With `refresh_budget` > 0 each round rebuilds the metric at the current Z
// (a QR each, counted down), else the given one is used throughout.
bool project_and_verify(const lmi::LmiProblem& lmi, const SparseBasis& basis, const VectorXd& c,
                        const ProjectionMetric& metric, MatrixXd& Z, const std::vector<lmi::SparseEntry>& basis_error,
                        const ScaledOperator& op, DualBound& out, int* refresh_budget = nullptr) {
  for (int round = 0; round < kProjectionRounds; ++round) {
    const bool refresh = refresh_budget && *refresh_budget > 0;
    if (refresh) --*refresh_budget;
    if (!(refresh ? project(lmi, basis, c, projection_metric(lmi, Z), Z) : project(lmi, basis, c, metric, Z))) break;
    DualBound candidate = out;
    if (verify_dual(lmi, basis, c, Z, basis_error, op, candidate)) {
      candidate.verified = true;
      candidate.detail.clear();
      out = candidate;
      return true;
    }
    out.detail = candidate.detail;
    out.residual_bound = candidate.residual_bound;
    out.correction_bound = candidate.correction_bound;
  }
  return false;
}

}  // namespace

DualBound verified_bracket(const lmi::LmiProblem& lmi, const VectorXd& c, const VectorXd& x, double margin,
                           const std::vector<lmi::SparseEntry>& basis_error, const std::vector<VectorXd>& path) {
  DualBound out;
  const SparseBasis basis = sparse_basis(lmi);
  out.upper_verified = verify_upper(lmi, basis, x, basis_error);
  if (out.upper_verified) out.upper_bound = c.dot(x);
  MatrixXd Zf;
  if (!central_dual_point(lmi, c, x, margin, Zf, out.detail)) return out;
  const VectorXd diag = Zf.diagonal();
  if (!(diag.minCoeff() > 0)) {
    out.detail = "the dual point has a non-positive diagonal entry";
    return out;
  }
  const ScaledOperator op = scaled_operator(lmi, basis, diag, basis_error);
  if (!(op.sigma > 0)) {
    out.detail = "the constraint matrices Mᵢ are not verifiably linearly independent";
    return out;
  }
  const MatrixXd Z0 = Zf;
  const ProjectionMetric metric = projection_metric(lmi, Z0);
  if (project_and_verify(lmi, basis, c, metric, Zf, basis_error, op, out)) return out;
  // Near the optimum Z is nearly singular (complementarity): shifts η·diag(Z₀) move it
  // inside the cone (the bound loses ~η·N relative), then projections.
  for (const double eta : kInteriorShifts) {
    MatrixXd Z = Z0;
    Z.diagonal() += eta * diag;
    if (project_and_verify(lmi, basis, c, metric, Z, basis_error, op, out)) return out;
  }
  // the metric of Z₀ may be too far from the shifted points': again, each round with its own
  int budget = kFreshMetrics;
  for (const double eta : kInteriorShifts) {
    if (budget <= 0) break;
    MatrixXd Z = Z0;
    Z.diagonal() += eta * diag;
    if (project_and_verify(lmi, basis, c, metric, Z, basis_error, op, out, &budget)) return out;
  }
  // Last: the dual points of earlier centred points of the path, newest first — further
  // inside the cone, with a gap about μ times larger each — alone, or pulling the final
  // one inside by the smallest weight θ that verifies (the bound then loses ~θ·their gap).
  int tried = 0;
  for (auto it = path.rbegin(); it != path.rend() && tried < kPathCandidates; ++it) {
    MatrixXd Zi;
    std::string why;
    if (it->size() != x.size() || (*it - x).norm() == 0 || !central_dual_point(lmi, c, *it, margin, Zi, why)) continue;
    ++tried;
    DualBound alone = out;
    const bool alone_ok = project_and_verify(lmi, basis, c, projection_metric(lmi, Zi), Zi, basis_error, op, alone);
    for (const double theta : kInteriorWeights) {
      MatrixXd Z = (1 - theta) * Zf + theta * Zi;
      DualBound candidate = out;
      if (verify_dual(lmi, basis, c, Z, basis_error, op, candidate) ||
          project_and_verify(lmi, basis, c, metric, Z, basis_error, op, candidate)) {
        candidate.verified = true;
        candidate.detail.clear();
        if (alone_ok && alone.lower_bound > candidate.lower_bound) break;
        return candidate;
      }
      out.detail = candidate.detail;
    }
    if (alone_ok) {
      alone.verified = true;
      alone.detail.clear();
      return alone;
    }
  }
  if (out.detail.empty()) out.detail = "the projections of the dual point did not lower its residual";
  return out;
}

// Phase I's LMI M(x) − sI (docs/maths.md (118)): the caller's with one more scalar
// parameter, last, entering every diagonal block as −I; minimise s.
DualBound verified_infeasibility(const lmi::LmiProblem& lmi, const VectorXd& z, double margin,
                                 const std::vector<lmi::SparseEntry>& basis_error, const std::vector<VectorXd>& path) {
  lmi::LmiProblem phase1 = lmi;
  const lmi::VarId s = phase1.add_scalar("s");
  for (int b = 0; b < phase1.num_blocks(); ++b)
    phase1.add_scalar_term(b, b, s, -MatrixXd::Identity(phase1.block_size(b), phase1.block_size(b)));
  return verified_bracket(phase1, phase1.cost_of(s), z, margin, basis_error, path);
}

}  // namespace hinf::sdp
