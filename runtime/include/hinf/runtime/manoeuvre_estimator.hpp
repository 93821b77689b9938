// The transient-model manoeuvre estimator (docs/maths.md §32.6): a linear Kalman filter of
// the relative state X = [position; velocity] (6) on the unforced relative model, fed with
// a position measurement, which reads the target's acceleration out of each correction:
//
//   X⁻ = Φ X (− Γ U_C with predict_with_chaser_control),  P⁻ = Φ P Φᵀ + Q_d
//   Joseph update on Y = [I₃ 0] X + v, v ~ N(0, R)                                  (223)
//   Û_T = [(X⁺ − X⁻)/Δt]_v + U_C  (without the + U_C when the prediction carried U_C)   (224)
//   P_U,paper = [P⁺ + Φ P Φᵀ]_vv / Δt²,   P_U,innov = [K S Kᵀ]_vv / Δt² = [P⁻ − P⁺]_vv / Δt²  (225)
//   D_k = Σ of the last w NIS,  alarm when D_k > threshold (a χ²_{3w} quantile)          (226)
//
// Φ, Q_d, Γ come from the model (models/elliptic_relative.hpp) for each sample. Fixed sizes;
// the detector's window is allocated by the constructor, a step allocates nothing.
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "hinf/runtime/detail/covariance.hpp"
#include "hinf/runtime/detail/joseph_update.hpp"
#include "hinf/runtime/filter_status.hpp"

namespace hinf::runtime {

struct ManoeuvreEstimatorSettings {
  bool predict_with_chaser_control = false;  // the source's prediction is unforced
  int nis_window = 0;                        // w; 0: no detector
  double nis_threshold = std::numeric_limits<double>::infinity();  // alarm when D_k exceeds it

  // Throws std::invalid_argument naming the field.
  void validate() const {
    if (nis_window < 0 || nis_window > 100000) throw std::invalid_argument("nis_window: must be in 0…100000");
    if (nis_window > 0 && !(nis_threshold > 0)) throw std::invalid_argument("nis_threshold: must be > 0");
  }
};

class TransientManoeuvreEstimator {
 public:
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  using Matrix63 = Eigen::Matrix<double, 6, 3>;
  using Vector3 = Eigen::Vector3d;
  using Matrix3 = Eigen::Matrix3d;

  explicit TransientManoeuvreEstimator(const ManoeuvreEstimatorSettings& s = {}) : s_(s) {
    s_.validate();
    window_.assign(static_cast<std::size_t>(s_.nis_window), 0.0);
    H_ << Matrix3::Identity(), Matrix3::Zero();
  }

  // X(t0|t0) and P(t0) (symmetric PD, else std::invalid_argument).
  void init(const Vector6& x0, const Matrix6& P0) {
    if (!x0.allFinite()) throw std::invalid_argument("TransientManoeuvreEstimator: x0 has a non-finite entry");
    detail::require_positive_definite(P0, "TransientManoeuvreEstimator", "P0");
    x_ = x0;
    P_ = 0.5 * (P0 + P0.transpose());
    filled_ = next_ = 0;
    window_sum_ = 0;
    alarm_ = false;
  }

  // One sample: Φ, Q_d (and Γ) over [t, t + Δt], the position measurement Y(t + Δt) and its
  // covariance R, the chaser's acceleration U_C over the sample. On a failed update x and P are
  // the prediction's and the manoeuvre estimate is not updated.
  FilterStatus step(const Matrix6& Phi, const Matrix6& Qd, const Matrix63& Gamma, const Vector3& y, const Matrix3& R,
                    const Vector3& u_chaser, double dt) {
    if (!y.allFinite() || !R.allFinite() || !u_chaser.allFinite() || !(dt > 0)) return FilterStatus::NonFiniteInput;
    if (!Phi.allFinite() || !Qd.allFinite() || !Gamma.allFinite()) return FilterStatus::ModelNotFinite;
    // (223) prediction
    x_prior_.noalias() = Phi * x_;
    if (s_.predict_with_chaser_control) x_prior_.noalias() -= Gamma * u_chaser;
    PhiPPhi_.noalias() = Phi * P_ * Phi.transpose();
    detail::symmetrise(PhiPPhi_);
    P_prior_ = PhiPPhi_ + Qd;
    detail::symmetrise(P_prior_);
    x_ = x_prior_;
    P_ = P_prior_;
    // (223) update
    const Vector3 nu = y - H_ * x_prior_;
    const FilterStatus status = detail::joseph_update<6, 3>(
        x_, P_, P_prior_, H_, R, nu, std::numeric_limits<double>::infinity(), nis_, S_, K_,
        [](Vector6& x, const Eigen::Matrix<double, 6, 3>& K, const Vector3& v) { x.noalias() += K * v; });
    if (status != FilterStatus::Ok) return status;
    // (224), (225)
    u_hat_ = (x_.tail<3>() - x_prior_.tail<3>()) / dt;
    if (!s_.predict_with_chaser_control) u_hat_ += u_chaser;
    const double dt2 = dt * dt;
    const Matrix6 KSK = K_ * S_ * K_.transpose();
    cov_innovation_ = KSK.bottomRightCorner<3, 3>() / dt2;
    cov_paper_ = (P_ + PhiPPhi_).bottomRightCorner<3, 3>() / dt2;
    detect();
    return FilterStatus::Ok;
  }

  const Vector6& x() const { return x_; }                // X(t+|t+)
  const Matrix6& P() const { return P_; }                // P(t+|t+)
  const Vector6& x_prior() const { return x_prior_; }    // X(t+|t)
  const Matrix6& P_prior() const { return P_prior_; }    // P(t+|t)
  const Vector3& manoeuvre() const { return u_hat_; }    // Û_T, time tag t (the sample's start)
  const Matrix3& manoeuvre_covariance_paper() const { return cov_paper_; }            // (225), the source's (7b)
  const Matrix3& manoeuvre_covariance_innovation() const { return cov_innovation_; }  // (225)
  double nis() const { return nis_; }
  double window_nis() const { return window_sum_; }  // D_k (226); over fewer samples until the window fills
  bool window_full() const { return filled_ == window_.size() && !window_.empty(); }
  bool alarm() const { return alarm_; }
  const ManoeuvreEstimatorSettings& settings() const { return s_; }

 private:
  // (226): the window sum is recomputed from the stored values, so that rounding cannot drift.
  void detect() {
    if (window_.empty()) return;
    window_[next_] = nis_;
    next_ = (next_ + 1) % window_.size();
    if (filled_ < window_.size()) ++filled_;
    window_sum_ = 0;
    for (std::size_t i = 0; i < filled_; ++i) window_sum_ += window_[i];
    alarm_ = window_full() && window_sum_ > s_.nis_threshold;
  }

  ManoeuvreEstimatorSettings s_;
  Eigen::Matrix<double, 3, 6> H_;
  Vector6 x_ = Vector6::Zero(), x_prior_ = Vector6::Zero();
  Matrix6 P_ = Matrix6::Identity(), P_prior_ = Matrix6::Identity(), PhiPPhi_ = Matrix6::Identity();
  Matrix3 S_ = Matrix3::Identity(), cov_paper_ = Matrix3::Zero(), cov_innovation_ = Matrix3::Zero();
  Eigen::Matrix<double, 6, 3> K_ = Eigen::Matrix<double, 6, 3>::Zero();
  Vector3 u_hat_ = Vector3::Zero();
  double nis_ = 0, window_sum_ = 0;
  std::vector<double> window_;
  std::size_t filled_ = 0, next_ = 0;
  bool alarm_ = false;
};

}  // namespace hinf::runtime
