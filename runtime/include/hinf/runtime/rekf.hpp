// Robust extended Kalman filter, SPEC §4 (seed 003: Xiong, Wei, Liu, IEEE T-SMC-A 40(2),
// 2010), in the consistent form fixed by the SPEC. Linearisation errors are norm-bounded
// uncertainties: process A_k beta L, measurement C_k alpha L, with scalar gamma > 0:
//
//     M(P)      = (P^-1 - gamma^-2 L^T L)^-1
//     P(k|k-1)  = F_k M(P(k-1)) F_k^T + gamma^2 A_k A_k^T + Q_k                         (14)
//     K_k       = M(P(k|k-1)) H_k^T [H_k M(P(k|k-1)) H_k^T + gamma^2 C_k C_k^T + R_k]^-1  (16)
//     P(k)      = (I - K_k H_k) M(P(k|k-1)) (I - K_k H_k)^T + K_k (gamma^2 C_k C_k^T + R_k) K_k^T  (15)
//     x(k|k-1)  = f(x(k-1), u),   x(k) = x(k|k-1) + K_k residual(y, h(x(k|k-1)))
//
// How M(P) is computed: by the matrix inversion lemma,
//     M(P) = P + P L^T (gamma^2 I - L P L^T)^-1 L P,
// with gamma^2 I - L P L^T factored by Cholesky (LLT) and the inverse applied by solves.
// Why: (i) the factorisation IS the existence condition gamma^2 I - L P L^T > 0 of SPEC §4,
// checked at every evaluation (in predict on P(k-1), in update on P(k|k-1)); (ii) P is
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

#include "hinf/runtime/detail/covariance.hpp"
#include "hinf/runtime/detail/joseph_update.hpp"
#include "hinf/runtime/filter_status.hpp"

namespace hinf::runtime {

template <class Model, class Measurement, int NL = Model::NX>
class Rekf {
 public:
  static constexpr int NX = Model::NX;
  static constexpr int NU = Model::NU;
  static constexpr int NZ = Measurement::NZ;
  static_assert(NX > 0 && NU > 0 && NZ > 0 && NL > 0, "Rekf: dimensions must be positive");
  static_assert(Measurement::NX == Model::NX, "Rekf: model and measurement state dimensions differ");

  using State = Eigen::Matrix<double, NX, 1>;
  using Input = Eigen::Matrix<double, NU, 1>;
  using Observation = Eigen::Matrix<double, NZ, 1>;
  using StateCov = Eigen::Matrix<double, NX, NX>;
  using ObsCov = Eigen::Matrix<double, NZ, NZ>;
  using Gain = Eigen::Matrix<double, NX, NZ>;
  using ProcessUncertainty = Eigen::Matrix<double, NX, NX>;      // A_k
  using MeasurementUncertainty = Eigen::Matrix<double, NZ, NZ>;  // C_k
  using UncertaintyOutput = Eigen::Matrix<double, NL, NX>;       // L

  // Q PSD, R PD, gamma > 0, A_k, C_k, L finite; throws std::invalid_argument otherwise.
  Rekf(const Model& model, const Measurement& measurement, const StateCov& Q, const ObsCov& R, double gamma,
       const ProcessUncertainty& A_k, const MeasurementUncertainty& C_k, const UncertaintyOutput& L)
      : model_(model), meas_(measurement) {
    set_Q(Q);
    set_R(R);
    set_gamma(gamma);
    set_uncertainty(A_k, C_k, L);
    x_.setZero();
    P_.setIdentity();
    P0_.setIdentity();
    M_.setZero();
    K_.setZero();
    S_.setZero();
    nu_.setZero();
  }

  void init(const State& x0, const StateCov& P0) {
    if (!x0.allFinite()) throw std::invalid_argument("Rekf: x0 has a non-finite entry");
    detail::require_positive_definite(P0, "Rekf", "P0");
    x_ = x0;
    P0_ = 0.5 * (P0 + P0.transpose());
    P_ = P0_;
  }

  // Eq. (14): P(k|k-1) = F M(P(k-1)) F^T + gamma^2 A_k A_k^T + Q.
  RekfStatus predict(const Input& u) {
    if (!u.allFinite()) return RekfStatus::NonFiniteInput;
    const State x_next = model_.f(x_, u);
    const StateCov F = model_.F(x_, u);
    if (!x_next.allFinite() || !F.allFinite()) return RekfStatus::ModelNotFinite;
    if (!compute_M(P_)) return RekfStatus::GammaConditionViolated;
    const StateCov FM = F * M_;
    P_.noalias() = FM * F.transpose();
    P_ += gamma2_AAt_;
    P_ += Q_;
    detail::symmetrise(P_);
    x_ = x_next;
    return detail::apply_covariance_policy<NX>(P_, P0_, policy_);
  }

  // Eqs. (16), (15) with M = M(P(k|k-1)) and R_bar = gamma^2 C_k C_k^T + R.
  RekfStatus update(const Observation& y) {
    if (!y.allFinite()) return RekfStatus::NonFiniteInput;
    const Observation y_pred = meas_.h(x_);
    const Eigen::Matrix<double, NZ, NX> H = meas_.H(x_);
    if (!y_pred.allFinite() || !H.allFinite()) return RekfStatus::ModelNotFinite;
    if (!compute_M(P_)) return RekfStatus::GammaConditionViolated;
    nu_ = meas_.residual(y, y_pred);
    const ObsCov R_bar = gamma2_CCt_ + R_;
    const RekfStatus s = detail::joseph_update<NX, NZ>(x_, P_, M_, H, R_bar, nu_, nis_gate_, nis_, S_, K_);
    if (s != RekfStatus::Ok) return s;
    return detail::apply_covariance_policy<NX>(P_, P0_, policy_);
  }

  // Smallest eigenvalue of gamma^2 I - L P L^T for the given P (on demand; not per step).
  double gamma_condition_min_eigenvalue_of(const StateCov& P) const {
    Eigen::Matrix<double, NL, NL> G = gamma_ * gamma_ * Eigen::Matrix<double, NL, NL>::Identity();
    G.noalias() -= L_ * P * L_.transpose();
    detail::symmetrise(G);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, NL, NL>> es(G, Eigen::EigenvaluesOnly);
    return es.eigenvalues().minCoeff();
  }

  // Configuration.
  void set_Q(const StateCov& Q) {
    detail::require_positive_semidefinite(Q, "Rekf", "Q");
    Q_ = 0.5 * (Q + Q.transpose());
  }
  void set_R(const ObsCov& R) {
    detail::require_positive_definite(R, "Rekf", "R");
    R_ = 0.5 * (R + R.transpose());
  }
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
  void set_covariance_policy(CovariancePolicy p) { policy_ = p; }
  void set_innovation_gate(double nis_threshold) { nis_gate_ = nis_threshold; }
  void set_state(const State& x, const StateCov& P) {
    x_ = x;
    P_ = P;
  }

  const State& x() const { return x_; }
  const StateCov& P() const { return P_; }
  const StateCov& P0() const { return P0_; }
  const StateCov& M() const { return M_; }  // M(P) of the last predict/update
  const Gain& K() const { return K_; }
  const ObsCov& S() const { return S_; }
  const Observation& innovation() const { return nu_; }
  double nis() const { return nis_; }
  double gamma() const { return gamma_; }
  // Smallest eigenvalue of gamma^2 I - L P L^T at the last violation (NaN if none yet).
  double gamma_condition_min_eigenvalue() const { return gamma_min_eig_; }
  const Model& model() const { return model_; }
  const Measurement& measurement() const { return meas_; }

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
    Eigen::LLT<Eigen::Matrix<double, NL, NL>> llt(G);
    if (!G.allFinite() || llt.info() != Eigen::Success) {
      gamma_min_eig_ = gamma_condition_min_eigenvalue_of(P);
      return false;
    }
    M_ = P;
    M_.noalias() += LP.transpose() * llt.solve(LP);
    detail::symmetrise(M_);
    return true;
  }

  Model model_;
  Measurement meas_;
  State x_;
  StateCov P_, P0_, Q_, M_, gamma2_AAt_;
  ObsCov R_, S_, gamma2_CCt_;
  Gain K_;
  Observation nu_;
  ProcessUncertainty A_k_ = ProcessUncertainty::Zero();
  MeasurementUncertainty C_k_ = MeasurementUncertainty::Zero();
  UncertaintyOutput L_ = UncertaintyOutput::Zero();
  double gamma_ = 1.0;
  double gamma_min_eig_ = std::numeric_limits<double>::quiet_NaN();
  double nis_ = 0.0;
  double nis_gate_ = std::numeric_limits<double>::infinity();
  CovariancePolicy policy_ = CovariancePolicy::Report;
};

}  // namespace hinf::runtime
