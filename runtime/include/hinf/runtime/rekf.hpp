// Robust extended Kalman filter, docs/maths.md §13 (Xiong, Wei, Liu, IEEE T-SMC-A 40(2),
// 2010), in the consistent form docs/maths.md (95)–(99) (see §16, item 7). Linearisation
// errors are norm-bounded uncertainties: process A_k beta L, measurement C_k alpha L, with
// scalar gamma > 0 (docs/maths.md (94)):
//
//     M(P)      = (P^-1 - gamma^-2 L^T L)^-1                                            (95)
//     P(k|k-1)  = F_k M(P(k-1)) F_k^T + gamma^2 A_k A_k^T + Q_k                         (96)
//     K_k       = M(P(k|k-1)) H_k^T [H_k M(P(k|k-1)) H_k^T + gamma^2 C_k C_k^T + R_k]^-1  (97)
//     P(k)      = (I - K_k H_k) M(P(k|k-1)) (I - K_k H_k)^T + K_k (gamma^2 C_k C_k^T + R_k) K_k^T  (98)
//     x(k|k-1)  = f(x(k-1), u),   x(k) = x(k|k-1) + K_k residual(y, h(x(k|k-1)))
//
// How M(P) is computed: by the matrix inversion lemma,
//     M(P) = P + P L^T (gamma^2 I - L P L^T)^-1 L P,
// with gamma^2 I - L P L^T factored by Cholesky (LLT) and the inverse applied by solves.
// Why: (i) the factorisation IS the existence condition gamma^2 I - L P L^T > 0, docs/maths.md
// (99), checked at every evaluation (in predict on P(k-1), in update on P(k|k-1)); (ii) P is
// never inverted, so an ill-conditioned P costs no accuracy; (iii) with L = 0 the
// correction term is exactly zero, so A_k = 0, C_k = 0, L = 0 gives exactly the EKF with
// the Joseph update (the update itself is shared with Ekf: detail/joseph_update.hpp).
// A violation is reported as RekfStatus::GammaConditionViolated, the step is skipped (x and
// P unchanged) and gamma_condition_min_eigenvalue() holds the smallest eigenvalue of
// gamma^2 I - L P L^T. Other failures follow filter_status.hpp.
//
// Dimensions: L is NL x NX (template parameter, default NX); A_k is NX x NX and C_k is
// NZ x NZ (any A_k A_k^T, C_k C_k^T is representable by a square factor, e.g. Cholesky).
// A_k, C_k, L and gamma may be changed between steps (set_uncertainty, set_gamma).
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "hinf/runtime/detail/kalman_core.hpp"
#include "hinf/runtime/filter_status.hpp"

namespace hinf::runtime {

template <class Model, class Measurement, int NL = Model::NX>
class Rekf : public detail::KalmanCore<Model, Measurement> {
  using Core = detail::KalmanCore<Model, Measurement>;

 public:
  static constexpr int NX = Core::NX;
  static constexpr int NZ = Core::NZ;
  static_assert(NL > 0, "Rekf: dimensions must be positive");
  using typename Core::Input;
  using typename Core::MeasurementJacobian;
  using typename Core::ObsCov;
  using typename Core::Observation;
  using typename Core::State;
  using typename Core::StateCov;
  using ProcessUncertainty = Eigen::Matrix<double, NX, NX>;      // A_k
  using MeasurementUncertainty = Eigen::Matrix<double, NZ, NZ>;  // C_k
  using UncertaintyOutput = Eigen::Matrix<double, NL, NX>;       // L

  // Q PSD, R PD, gamma > 0, A_k, C_k, L finite; throws std::invalid_argument otherwise.
  Rekf(const Model& model, const Measurement& measurement, const StateCov& Q, const ObsCov& R, double gamma,
       const ProcessUncertainty& A_k, const MeasurementUncertainty& C_k, const UncertaintyOutput& L)
      : Core(model, measurement, Q, R, "Rekf") {
    set_gamma(gamma);
    set_uncertainty(A_k, C_k, L);
    M_.setZero();
  }

  // docs/maths.md (96): P(k|k-1) = F M(P(k-1)) F^T + gamma^2 A_k A_k^T + Q.
  RekfStatus predict(const Input& u) {
    State x_next;
    StateCov F;
    const RekfStatus s = this->evaluate_process(u, x_next, F);
    if (s != RekfStatus::Ok) return s;
    if (!compute_M(this->P_)) return RekfStatus::GammaConditionViolated;
    return this->finish_predict(x_next, F, M_, &gamma2_AAt_);
  }

  // docs/maths.md (97), (98) with M = M(P(k|k-1)) and R_bar = gamma^2 C_k C_k^T + R.
  RekfStatus update(const Observation& y) {
    Observation y_pred;
    MeasurementJacobian H;
    const RekfStatus s = this->evaluate_measurement(y, y_pred, H);
    if (s != RekfStatus::Ok) return s;
    if (!compute_M(this->P_)) return RekfStatus::GammaConditionViolated;
    const ObsCov R_bar = gamma2_CCt_ + this->R_;
    return this->finish_update(y, y_pred, H, M_, R_bar);
  }

  // Smallest eigenvalue of gamma^2 I - L P L^T for the given P (on demand; not per step).
  double gamma_condition_min_eigenvalue_of(const StateCov& P) const {
    Eigen::Matrix<double, NL, NL> G = gamma_ * gamma_ * Eigen::Matrix<double, NL, NL>::Identity();
    G.noalias() -= L_ * P * L_.transpose();
    detail::symmetrise(G);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, NL, NL>> es(G, Eigen::EigenvaluesOnly);
    return es.eigenvalues().minCoeff();
  }

  // Configuration (also Core's set_Q, set_R, set_covariance_policy, set_innovation_gate, set_state).
  void set_gamma(double gamma) {
    if (!std::isfinite(gamma) || gamma <= 0.0)
      throw std::invalid_argument("Rekf: gamma must be finite and > 0; got " + std::to_string(gamma));
    gamma_ = gamma;
    refresh_uncertainty_terms();
  }
  void set_uncertainty(const ProcessUncertainty& A_k, const MeasurementUncertainty& C_k, const UncertaintyOutput& L) {
    if (!A_k.allFinite()) throw std::invalid_argument("Rekf: A_k has a non-finite entry");
    if (!C_k.allFinite()) throw std::invalid_argument("Rekf: C_k has a non-finite entry");
    if (!L.allFinite()) throw std::invalid_argument("Rekf: L has a non-finite entry");
    A_k_ = A_k;
    C_k_ = C_k;
    L_ = L;
    refresh_uncertainty_terms();
  }

  const StateCov& M() const { return M_; }  // M(P) of the last predict/update
  double gamma() const { return gamma_; }
  // Smallest eigenvalue of gamma^2 I - L P L^T at the last violation (NaN if none yet).
  double gamma_condition_min_eigenvalue() const { return gamma_min_eig_; }

 private:
  void refresh_uncertainty_terms() {
    const double g2 = gamma_ * gamma_;
    gamma2_AAt_.noalias() = g2 * A_k_ * A_k_.transpose();
    gamma2_CCt_.noalias() = g2 * C_k_ * C_k_.transpose();
  }

  // M_ = P + (L P)^T (gamma^2 I - L P L^T)^-1 (L P); false (and gamma_min_eig_ set) if the
  // Cholesky factorisation of gamma^2 I - L P L^T fails.
  bool compute_M(const StateCov& P) {
    const Eigen::Matrix<double, NL, NX> LP = L_ * P;
    Eigen::Matrix<double, NL, NL> G = gamma_ * gamma_ * Eigen::Matrix<double, NL, NL>::Identity();
    G.noalias() -= LP * L_.transpose();
    detail::symmetrise(G);
    const detail::SmallLlt<NL> llt(G);
    if (!detail::all_finite(G) || !llt.ok()) {
      gamma_min_eig_ = gamma_condition_min_eigenvalue_of(P);
      return false;
    }
    M_ = P;
    M_.noalias() += LP.transpose() * llt.solve(LP);
    detail::symmetrise(M_);
    return true;
  }

  StateCov M_, gamma2_AAt_;
  ObsCov gamma2_CCt_;
  ProcessUncertainty A_k_ = ProcessUncertainty::Zero();
  MeasurementUncertainty C_k_ = MeasurementUncertainty::Zero();
  UncertaintyOutput L_ = UncertaintyOutput::Zero();
  double gamma_ = 1.0;
  double gamma_min_eig_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace hinf::runtime
