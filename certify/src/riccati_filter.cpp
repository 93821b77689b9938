// Stationary H∞ a priori filter by the Krein-space Riccati equation; see
// riccati_filter.hpp for the equations and references.
//
// The filter DARE P = Q + A P (I + G P)⁻¹ Aᵀ (Q = B Bᵀ) is the control-form DARE of
// the dual system (Aᵀ, Hᵀ): the Hamiltonian recursion x(k+1) = Aᵀx(k) − G λ(k+1),
// λ(k) = Q x(k) + A λ(k+1), λ = P x, gives the symplectic pencil
//     [Aᵀ 0; −Q I] ξ = z [I G; 0 A] ξ,
// whose stable deflating subspace span[U₁; U₂] yields P = U₂ U₁⁻¹ and the closed loop
// (I + G P)⁻¹ Aᵀ = (A (I + P G)⁻¹)ᵀ (Pappas, Laub & Sandell, IEEE TAC 25(4), 1980;
// Van Dooren, SIAM J. Sci. Stat. Comput. 2(2), 1981: ordered QZ, no inverse of A).
#include "hinf/certify/riccati_filter.hpp"

#include <cmath>
#include <optional>
#include <limits>
#include <sstream>

#include "qz.hpp"
#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/stability.hpp"
#include "hinf/common/error.hpp"

namespace hinf::certify {
namespace {

// Eigenvalues of the pencil within this distance of the unit circle: no dichotomy.
constexpr double kDichotomyTolerance = 1e-9;
// U₁ reciprocal condition number below this: no finite stabilising solution.
constexpr double kMinRcondU1 = 1e-13;

void validate_nominal(const Plant& plant) {
  const Eigen::Index n = plant.A.rows();
  std::ostringstream msg;
  if (plant.A.cols() != n || plant.B.rows() != n || plant.C.cols() != n ||
      plant.D.rows() != plant.C.rows() || plant.L.cols() != n)
    msg << "inconsistent plant dimensions";
  else if (!plant.A.allFinite() || !plant.B.allFinite() || !plant.C.allFinite() ||
           !plant.D.allFinite() || !plant.L.allFinite())
    msg << "non-finite plant entry";
  if (!msg.str().empty())
    throw Error(ErrorCode::InvalidInput, "H∞ predictor Riccati: " + msg.str());
}

double min_eigenvalue(const Eigen::MatrixXd& S) {
  if (S.size() == 0) return std::numeric_limits<double>::infinity();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S, Eigen::EigenvaluesOnly);
  return es.eigenvalues()(0);
}

// The stabilising solution P of the DARE of docs/maths.md (56) (G of (55)), P = Q + A P (I + G P)⁻¹ Aᵀ,
// from the stable deflating subspace [U₁; U₂] of the symplectic pencil (M, N): P U₁ = U₂.
// Empty with `reason` set when there is none (eigenvalues on the unit circle, U₁
// singular, or a numerically unsymmetric solution).
std::optional<Eigen::MatrixXd> stabilising_dare_solution(const Eigen::MatrixXd& A, const Eigen::MatrixXd& G,
                                                         const Eigen::MatrixXd& Q, std::string& reason) {
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2 * n, 2 * n), N = M;
  M.topLeftCorner(n, n) = A.transpose();
  M.bottomLeftCorner(n, n) = -Q;
  M.bottomRightCorner(n, n).setIdentity();
  N.topLeftCorner(n, n).setIdentity();
  N.topRightCorner(n, n) = G;
  N.bottomRightCorner(n, n) = A;
  const detail::OrderedQz qz = detail::ordered_qz_stable_first(M, N);

  double circle_distance = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < qz.beta.size(); ++i) {
    if (qz.beta(i) == 0.0) continue;
    circle_distance = std::min(circle_distance, std::abs(std::abs(qz.alpha(i)) / std::abs(qz.beta(i)) - 1.0));
  }
  if (qz.reordering_failed || qz.stable_count != n || circle_distance <= kDichotomyTolerance) {
    std::ostringstream msg;
    msg << "no stabilising solution: symplectic pencil has eigenvalues on the unit circle "
        << "(distance " << circle_distance << ", " << qz.stable_count << " inside, need " << n << ")";
    reason = msg.str();
    return std::nullopt;
  }
  const Eigen::MatrixXd U1 = qz.Z.topLeftCorner(n, n), U2 = qz.Z.bottomLeftCorner(n, n);
  const Eigen::PartialPivLU<Eigen::MatrixXd> U1t_lu(U1.transpose());
  if (n > 0 && !(U1t_lu.rcond() > kMinRcondU1)) {
    reason = "no finite stabilising solution (U₁ singular, rcond " + std::to_string(U1t_lu.rcond()) + ")";
    return std::nullopt;
  }
  const Eigen::MatrixXd X = U1t_lu.solve(U2.transpose()).transpose();  // X U₁ = U₂
  const double X_norm = std::max(1.0, X.norm());
  if ((X - X.transpose()).norm() > 1e-6 * X_norm) {
    reason = "Riccati solution not symmetric to 1e-6 (numerically unreliable)";
    return std::nullopt;
  }
  return Eigen::MatrixXd(0.5 * (X + X.transpose()));
}


// The observer-form predictor x̂(k+1) = A x̂ + G u + K (y − C x̂) (docs/maths.md (121)).
Filter observer_filter(const Plant& plant, const Eigen::MatrixXd& K) {
  Filter f;
  f.form = FilterForm::Observer;
  f.K = K;
  f.A_F = plant.A - K * plant.C;
  f.B_F = K;
  f.C_F = plant.L;
  f.G_F = plant.G.size() > 0 ? plant.G : Eigen::MatrixXd::Zero(plant.n(), 0);
  return f;
}

// The a posteriori condition (ii') and central filter (143) from the stabilising P in `out`.
HinfPredictorLevel central_filtered(const Plant& plant, double gamma, const Eigen::MatrixXd& R,
                                    HinfPredictorLevel out) {
  const Eigen::MatrixXd& P = out.P;
  const Eigen::MatrixXd& C = plant.C;
  const Eigen::MatrixXd& L = plant.L;
  const Eigen::LLT<Eigen::MatrixXd> Re(R + C * P * C.transpose());
  const Eigen::MatrixXd M = Re.solve(C * P).transpose();  // M = P Cᵀ (R + C P Cᵀ)⁻¹
  if (std::isinf(gamma)) {
    out.min_eig_gamma2_minus_LPL = std::numeric_limits<double>::infinity();
  } else {
    const Eigen::MatrixXd Pf = P - M * C * P;
    const Eigen::MatrixXd W = gamma * gamma * Eigen::MatrixXd::Identity(L.rows(), L.rows()) - L * Pf * L.transpose();
    out.min_eig_gamma2_minus_LPL = min_eigenvalue(0.5 * (W + W.transpose()));
    if (!(out.min_eig_gamma2_minus_LPL > 0)) {
      out.reason = "a posteriori condition γ²I − L P_f Lᵀ > 0 violated";
      return out;
    }
  }
  out.filter = observer_filter(plant, plant.A * M);
  out.filter.M = M;
  out.filter.D_F = L * M;
  out.filter.C_F = L - out.filter.D_F * C;
  out.feasible = true;
  return out;
}

}  // namespace

HinfPredictorLevel hinf_predictor_at_level(const Plant& plant, double gamma, Estimate estimate) {
  validate_nominal(plant);
  if (!(gamma > 0)) throw Error(ErrorCode::InvalidInput, "H∞ predictor Riccati: gamma must be > 0");
  const Eigen::Index n = plant.A.rows(), l = plant.L.rows();
  const Eigen::MatrixXd& A = plant.A;
  const Eigen::MatrixXd& C = plant.C;
  const Eigen::MatrixXd& L = plant.L;
  const Eigen::MatrixXd R = plant.D * plant.D.transpose();
  const Eigen::LLT<Eigen::MatrixXd> R_llt(R);
  if (R_llt.info() != Eigen::Success)
    throw Error(ErrorCode::InvalidInput,
                "H∞ predictor Riccati: D Dᵀ is not positive definite (D needs full row rank)");
  const bool kalman = std::isinf(gamma);

  HinfPredictorLevel out;
  out.gamma = gamma;
  // G = Cᵀ R⁻¹ C − γ⁻² LᵀL, Q = B Bᵀ.
  Eigen::MatrixXd G = C.transpose() * R_llt.solve(C);
  if (!kalman) G -= (L.transpose() * L) / (gamma * gamma);
  G = 0.5 * (G + G.transpose());
  const Eigen::MatrixXd Q = plant.B * plant.B.transpose();
  const std::optional<Eigen::MatrixXd> solution = stabilising_dare_solution(A, G, Q, out.reason);
  if (!solution) return out;
  const Eigen::MatrixXd& P = *solution;
  out.P = P;

  // Closed loop (I + G P)⁻¹ Aᵀ = (A (I + P G)⁻¹)ᵀ and the DARE residual.
  const Eigen::MatrixXd I_GP = Eigen::MatrixXd::Identity(n, n) + G * P;
  const Eigen::MatrixXd Y = I_GP.partialPivLu().solve(A.transpose());
  out.closed_loop_spectral_radius = spectral_radius(Y);
  out.riccati_residual = (P - (Q + A * P * Y)).norm() / std::max(1.0, P.norm());
  if (!(out.closed_loop_spectral_radius < 1.0)) {
    out.reason = "Riccati solution is not stabilising";
    return out;
  }
  const double P_scale = std::max(1e-300, P.norm());
  if (min_eigenvalue(P) < -1e-10 * P_scale) {
    out.reason = "stabilising solution P is not positive semidefinite";
    return out;
  }
  if (estimate == Estimate::Filtered) return central_filtered(plant, gamma, R, std::move(out));
  Eigen::MatrixXd Ptilde = P;  // P̃ = (P⁻¹ − γ⁻² LᵀL)⁻¹
  if (kalman) {
    out.min_eig_gamma2_minus_LPL = std::numeric_limits<double>::infinity();
  } else {
    const Eigen::MatrixXd W = gamma * gamma * Eigen::MatrixXd::Identity(l, l) - L * P * L.transpose();
    out.min_eig_gamma2_minus_LPL = min_eigenvalue(W);
    const Eigen::LLT<Eigen::MatrixXd> W_llt(W);
    if (!(out.min_eig_gamma2_minus_LPL > 0) || W_llt.info() != Eigen::Success) {
      out.reason = "a priori condition γ²I − L P Lᵀ > 0 violated";
      return out;
    }
    Ptilde += P * L.transpose() * W_llt.solve(L * P);
  }
  // K = A P̃ Cᵀ (R + C P̃ Cᵀ)⁻¹, computed as Kᵀ = (R + C P̃ Cᵀ)⁻¹ C P̃ Aᵀ.
  const Eigen::MatrixXd Re = R + C * Ptilde * C.transpose();
  const Eigen::MatrixXd K = Re.llt().solve(C * Ptilde * A.transpose()).transpose();
  out.filter = observer_filter(plant, K);  // (59): x̂(k+1) = A x̂ + G u + K (y − C x̂)
  out.feasible = true;
  return out;
}

HinfPredictorOptimum optimal_hinf_predictor(const Plant& plant, double rel_tol, Estimate estimate) {
  if (!(rel_tol > 0 && rel_tol < 1))
    throw Error(ErrorCode::InvalidInput, "optimal_hinf_predictor: rel_tol must be in (0, 1)");
  const HinfPredictorLevel kalman =
      hinf_predictor_at_level(plant, std::numeric_limits<double>::infinity(), estimate);
  if (!kalman.feasible)
    throw Error(ErrorCode::NumericalFailure, "optimal_hinf_predictor: Kalman predictor DARE failed: " + kalman.reason);
  Plant nominal = plant;
  nominal.H.resize(plant.n(), 0);
  nominal.E.resize(0, plant.n());
  const double gamma_kalman = discrete_hinf_norm(error_system(nominal, kalman.filter)).norm;

  HinfPredictorOptimum out;
  double lo = 0;
  if (estimate == Estimate::Predicted) {
    const Eigen::MatrixXd LB = plant.L * plant.B;
    if (LB.size() > 0) lo = Eigen::JacobiSVD<Eigen::MatrixXd>(LB).singularValues()(0);
  }
  double hi = std::max(gamma_kalman * (1 + 1e-6), lo * (1 + rel_tol));
  HinfPredictorLevel at_hi = hinf_predictor_at_level(plant, hi, estimate);
  for (int i = 0; i < 60 && !at_hi.feasible; ++i) {
    hi *= 2;
    at_hi = hinf_predictor_at_level(plant, hi, estimate);
  }
  if (!at_hi.feasible)
    throw Error(ErrorCode::NumericalFailure,
                "optimal_hinf_predictor: no feasible level found above the Kalman predictor's norm: " + at_hi.reason);
  int steps = 0;
  while (hi > lo * (1 + rel_tol) && steps < 200 && hi > 1e-300) {
    const double mid = lo > 0 ? std::sqrt(lo * hi) : 0.5 * hi;
    HinfPredictorLevel at_mid = hinf_predictor_at_level(plant, mid, estimate);
    if (at_mid.feasible) { hi = mid; at_hi = std::move(at_mid); }
    else lo = mid;
    ++steps;
  }
  out.gamma = hi;
  out.gamma_infeasible = lo;
  out.bisection_steps = steps;
  out.at_gamma = std::move(at_hi);
  return out;
}

double optimal_hinf_predictor_gamma(const Plant& plant, double rel_tol, Estimate estimate) {
  return optimal_hinf_predictor(plant, rel_tol, estimate).gamma;
}

}  // namespace hinf::certify
