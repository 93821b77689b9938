// Discrete-time H∞ norm by the Bruinsma–Steinbuch / Boyd–Balakrishnan two-step
// algorithm on the symplectic pencil; see hinf_norm.hpp.
//
// Level-set test (derivation). Let |z| = 1, z not an eigenvalue of A (A Schur stable).
// γ is a singular value of G(z) iff G u = γ v and G(z)ᴴ v = γ u for some (u, v) ≠ 0.
// With x = (zI − A)⁻¹ B u and p = (z⁻¹ I − Aᵀ)⁻¹ Cᵀ v (note G(z)ᴴ = Bᵀ(z̄I − Aᵀ)⁻¹Cᵀ + Dᵀ
// and z̄ = z⁻¹ on the unit circle):
//     z x = A x + B u,            p = z (Aᵀ p + Cᵀ v),
//     [γI −Dᵀ; −D γI] [u; v] = [Bᵀ p; C x]   =:  𝓜 [u; v] = [0 Bᵀ; C 0] [x; p].
// For γ > σ_max(D) the matrix 𝓜 is nonsingular; [u; v] = K [x; p] with
// K = 𝓜⁻¹ [0 Bᵀ; C 0] = [K_ux K_up; K_vx K_vp], and (x, p) solves the pencil
//     [A + B K_ux, B K_up; 0, I] ξ = z [I, 0; Cᵀ K_vx, Aᵀ + Cᵀ K_vp] ξ.          (★)
// Conversely an eigenvalue of (★) on the unit circle gives (u, v) ≠ 0 (if u = v = 0
// then x and p would be eigenvectors of A and Aᵀ for |z| = 1, impossible for A Schur).
// So the frequencies θ ∈ [0, π] where σ_i(G(e^{jθ})) = γ for some i are exactly the
// arguments of the unit-circle eigenvalues of (★).
//
// Two-step iteration (Bruinsma–Steinbuch 1990, §3): with a lower bound γ_lb (attained
// σ_max values), test γ = (1 + rel_tol) γ_lb. If ‖G‖∞ > γ, the set {θ: σ_max > γ} is a
// union of intervals whose ends are unit-circle eigenvalues of (★) (σ_max(0) and
// σ_max(π) are ≤ γ_lb < γ, so no interval touches 0 or π); σ_max at the midpoint of
// consecutive candidate frequencies then exceeds γ and raises γ_lb. If no midpoint
// exceeds γ, γ ≥ ‖G‖∞ is certified. Every finite eigenvalue's argument is a candidate,
// not only those near the circle: a spurious candidate costs two frequency evaluations, a
// missed one the certificate (any superset of the crossings keeps the test exact: an
// interval where σ_max > γ still has a test point inside). Rounding moves a crossing's
// eigenvalue off the circle by its conditioning, which near z = 1 can be large: the loop of
// a double integrator sampled at T = 0.01 s with its controller has its crossings at
// | |z| − 1 | ≈ 1.5e-3, and a tolerance of 1e-5 there certified 2.669514 for a norm of
// 2.671518 (tests/certify/test_hinf_norm.cpp, PencilCrossingsOffTheCircleAreNotMissed).
// The pencil is formed on the balanced realisation (D⁻¹AD, D⁻¹B, CD, D powers of two:
// the same transfer function exactly, docs/maths.md §4.4); G is evaluated on the given one.
//
// σ_max(D) ≤ ‖G‖∞ by the maximum modulus principle (G is analytic in |z| ≥ 1,
// including z = ∞ where G = D), so σ_max(D) is a valid lower bound and keeps 𝓜
// nonsingular.
#include "hinf/certify/hinf_norm.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>
#include <string>
#include <vector>

#include "frequency_response.hpp"
#include "golden_section.hpp"
#include "hinf/certify/balance.hpp"
#include "hinf/common/error.hpp"
#include "qz.hpp"

namespace hinf::certify {
namespace {

constexpr int kMaxIterations = 60;
// Golden-section steps per local search (bracket shrinks by 0.618 per step; near a
// smooth peak σ_max is flat, so 0.618²² ≈ 2.5e-5 of the bracket already gives it to
// ~1e-9 relative, and the level-set iteration, not this search, certifies the norm).
constexpr int kGoldenSteps = 22;
// ... or until the bracket in θ is this narrow.
constexpr double kPeakWidth = 1e-12;

void validate(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
              const Eigen::MatrixXd& D, double rel_tol) {
  std::ostringstream msg;
  if (A.rows() != A.cols()) msg << "A is " << A.rows() << "×" << A.cols() << ", not square";
  else if (B.rows() != A.rows()) msg << "B has " << B.rows() << " rows, A has " << A.rows();
  else if (C.cols() != A.rows()) msg << "C has " << C.cols() << " columns, A has " << A.rows();
  else if (D.rows() != C.rows() || D.cols() != B.cols())
    msg << "D is " << D.rows() << "×" << D.cols() << ", expected " << C.rows() << "×" << B.cols();
  else if (!A.allFinite() || !B.allFinite() || !C.allFinite() || !D.allFinite())
    msg << "non-finite entry in (A, B, C, D)";
  else if (!(rel_tol >= 1e-14 && rel_tol < 1))
    msg << "rel_tol = " << rel_tol << " outside [1e-14, 1)";
  if (!msg.str().empty())
    throw Error(ErrorCode::InvalidInput, "discrete_hinf_norm: " + msg.str());
}

double sigma_max(const Eigen::MatrixXd& M) {
  if (M.size() == 0) return 0.0;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(M);
  return svd.singularValues()(0);
}

// Arguments in [0, π] of the finite eigenvalues of the pencil (★), for the system
// (A, B, C, D) at level gamma (gamma > σ_max(D)): a superset of the crossings' frequencies.
std::vector<double> crossing_candidates(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                            const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                                            double gamma) {
  const Eigen::Index n = A.rows(), p = B.cols(), l = C.rows();
  Eigen::MatrixXd Mcal(p + l, p + l);
  Mcal << gamma * Eigen::MatrixXd::Identity(p, p), -D.transpose(),
          -D, gamma * Eigen::MatrixXd::Identity(l, l);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(p + l, 2 * n);
  rhs.block(0, n, p, n) = B.transpose();
  rhs.block(p, 0, l, n) = C;
  const Eigen::MatrixXd K = Mcal.partialPivLu().solve(rhs);
  const auto Kux = K.block(0, 0, p, n), Kup = K.block(0, n, p, n);
  const auto Kvx = K.block(p, 0, l, n), Kvp = K.block(p, n, l, n);

  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2 * n, 2 * n), N = M;
  M.topLeftCorner(n, n) = A + B * Kux;
  M.topRightCorner(n, n) = B * Kup;
  M.bottomRightCorner(n, n).setIdentity();
  N.topLeftCorner(n, n).setIdentity();
  N.bottomLeftCorner(n, n) = C.transpose() * Kvx;
  N.bottomRightCorner(n, n) = A.transpose() + C.transpose() * Kvp;

  const detail::PencilEigenvalues ev = detail::pencil_eigenvalues(M, N);
  std::vector<double> thetas;
  for (Eigen::Index i = 0; i < ev.beta.size(); ++i) {
    if (ev.beta(i) == 0.0) continue;
    const std::complex<double> z = ev.alpha(i) / ev.beta(i);
    thetas.push_back(std::abs(std::arg(z)));  // every one: see the note at the top
  }
  std::sort(thetas.begin(), thetas.end());
  thetas.erase(std::unique(thetas.begin(), thetas.end()), thetas.end());
  return thetas;
}

// The poles of G (eigenvalues of A); throws unless A is Schur stable (the norm is then
// infinite: exit 3).
Eigen::VectorXcd stable_poles(const Eigen::MatrixXd& A) {
  if (A.rows() == 0) return Eigen::VectorXcd(0);
  // balanced, as every spectral radius of the project (docs/maths.md §4.4): the same ρ as
  // certify::spectral_radius, so a caller that checked ρ < 1 first is never contradicted
  const Eigen::VectorXcd poles = balanced_eigenvalues(A);
  const double rho = poles.cwiseAbs().maxCoeff();
  if (!(rho < 1.0)) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "discrete_hinf_norm: A is not Schur stable (spectral radius " << rho
        << " >= 1); the H∞ norm is infinite";
    throw Error(ErrorCode::Infeasible, msg.str());
  }
  return poles;
}

// The largest σ_max(G(e^{jθ})) evaluated so far (a certified lower bound on ‖G‖∞) and
// where, with a golden-section search for a local maximum on [a, b] (speed only: it
// raises the lower bound so that fewer pencil eigenproblems are needed; every value it
// finds is an attained σ_max, so correctness does not depend on unimodality).
class PeakSearch {
 public:
  explicit PeakSearch(const detail::FrequencyResponse& response) : response_(response) {}

  double evaluate(double theta) {
    const double s = response_.sigma_max(theta);
    if (s > attained_) { attained_ = s; peak_ = theta; }
    return s;
  }
  // A local maximum of σ_max on [a, b]: the minimum of −σ_max, to kPeakWidth in θ.
  void refine(double a, double b) {
    detail::golden_section_minimise([this](double theta) { return -evaluate(theta); }, a, b,
                                    kGoldenSteps, [](double l, double r) { return r - l <= kPeakWidth; });
  }
  double attained() const { return attained_; }
  double peak() const { return peak_; }

 private:
  const detail::FrequencyResponse& response_;
  double attained_ = 0, peak_ = 0;
};

// Initial lower bound: θ = 0, π and the arguments of the poles (Bruinsma–Steinbuch use
// the pole with the largest ratio |Im|/|Re|; evaluating all of them is cheap), then a local
// search between the neighbours of the best of these. False if G ≡ 0 (and σ_max(D) = 0).
bool initial_lower_bound(PeakSearch& search, const Eigen::VectorXcd& poles, Eigen::Index n, double sigma_D) {
  std::vector<double> initial{0.0, detail::kPi};
  for (Eigen::Index i = 0; i < poles.size(); ++i) initial.push_back(std::abs(std::arg(poles(i))));
  std::sort(initial.begin(), initial.end());
  initial.erase(std::unique(initial.begin(), initial.end()), initial.end());
  for (double theta : initial) search.evaluate(theta);
  if (search.attained() == 0.0) {
    // A rational matrix of McMillan degree ≤ n that vanishes at n + 1 distinct points
    // of the unit circle vanishes identically (each entry's numerator has degree ≤ n).
    for (Eigen::Index i = 0; i <= n && search.attained() == 0.0; ++i)
      search.evaluate(detail::kPi * (static_cast<double>(i) + 0.5) / static_cast<double>(n + 1));
    if (search.attained() == 0.0 && sigma_D == 0.0) return false;
  }
  if (search.attained() > 0.0) {
    const auto it = std::lower_bound(initial.begin(), initial.end(), search.peak());
    const double left = it == initial.begin() ? 0.0 : *(it - 1);
    const double right = (it == initial.end() || it + 1 == initial.end()) ? detail::kPi : *(it + 1);
    search.refine(left, right);
  }
  return true;
}

// A test frequency with the bracket it lies in.
struct TestPoint {
  double theta, left, right;
};

// Midpoints of consecutive level-set frequencies (and of the end intervals) and the
// frequencies themselves.
std::vector<TestPoint> test_points(const std::vector<double>& thetas) {
  std::vector<TestPoint> points;
  if (thetas.empty()) return points;
  points.push_back({0.5 * thetas.front(), 0.0, thetas.front()});
  for (std::size_t i = 0; i < thetas.size(); ++i) {
    const double next = i + 1 < thetas.size() ? thetas[i + 1] : detail::kPi;
    points.push_back({thetas[i], i > 0 ? thetas[i - 1] : 0.0, next});
    points.push_back({0.5 * (thetas[i] + next), thetas[i], next});
  }
  return points;
}

}  // namespace

// Bruinsma–Steinbuch level-set iteration (docs/maths.md (48)–(49)): at γ = (1 + tol)·(lower
// bound), the unit-circle eigenvalues of the symplectic pencil are where σ_max(G) = γ; if no
// test point between them exceeds γ, ‖G‖∞ ≤ γ; else the lower bound rises.
HinfNorm discrete_hinf_norm(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                            const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                            double rel_tol) {
  validate(A, B, C, D, rel_tol);
  const Eigen::Index n = A.rows();
  HinfNorm result;
  const double sigma_D = sigma_max(D);
  const Eigen::VectorXcd poles = stable_poles(A);
  if (n == 0 || B.cols() == 0 || C.rows() == 0) {
    result.norm = result.lower_bound = sigma_D;
    return result;
  }
  const detail::FrequencyResponse response(A, B, C, D);
  PeakSearch search(response);
  if (!initial_lower_bound(search, poles, n, sigma_D)) return result;  // G ≡ 0

  // Work with G/s (s = initial lower bound) so that the tested level is O(1).
  const double s = std::max(search.attained(), sigma_D);
  const Eigen::VectorXd d = balancing_scaling(A, B, C);
  const Eigen::MatrixXd Ab = d.cwiseInverse().asDiagonal() * A * d.asDiagonal();
  const Eigen::MatrixXd Bs = d.cwiseInverse().asDiagonal() * B / s, Cb = C * d.asDiagonal(), Ds = D / s;
  for (int iter = 1; iter <= kMaxIterations; ++iter) {
    const double gamma = (1.0 + rel_tol) * std::max(search.attained(), sigma_D);
    result.iterations = iter;
    const std::vector<TestPoint> points = test_points(crossing_candidates(Ab, Bs, Cb, Ds, gamma / s));
    double best = 0;
    const TestPoint* best_point = nullptr;
    for (const TestPoint& tp : points) {
      const double value = search.evaluate(tp.theta);
      if (value > best) { best = value; best_point = &tp; }
    }
    if (!(best > gamma)) {
      result.norm = gamma;
      result.peak_frequency = search.peak();
      result.lower_bound = search.attained();
      return result;
    }
    search.refine(best_point->left, best_point->right);
  }
  throw Error(ErrorCode::NumericalFailure,
              "discrete_hinf_norm: no convergence in " + std::to_string(kMaxIterations) +
                  " level-set iterations");
}

HinfNorm discrete_hinf_norm(const StateSpace& system, double rel_tol) {
  return discrete_hinf_norm(system.A, system.B, system.C, system.D, rel_tol);
}

}  // namespace hinf::certify
