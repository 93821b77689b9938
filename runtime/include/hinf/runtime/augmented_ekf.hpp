// The augmented EKF (docs/maths.md §31.4): an EKF whose step is
//     predict the state → residual at the prediction → policy → P⁻ → gain → Joseph update
// (209), generic over the process model, the measurement and the prior-covariance policy of
// prior_covariance.hpp (PlainPrior: the AEKF; AdaptiveQ: the AAEKF; StrongTracking: the
// ASTEKF). With PlainPrior a step is Ekf::predict followed by Ekf::update, bit for bit.
//
// Model and measurement as for Ekf (ekf.hpp), with NS and boxplus where the state is not its
// error (kalman_core.hpp). A chart switch (normalise) is not supported here: the residual is
// taken at the predicted state before P⁻ exists, so a switch between them would leave H in
// the wrong chart.
//
// A step that would leave x or P non-finite is undone and stops the filter (StateNotFinite;
// every later step returns Stopped). Fixed sizes: no heap allocation in step().
#pragma once

#include <Eigen/Dense>

#include "hinf/runtime/detail/kalman_core.hpp"
#include "hinf/runtime/filter_status.hpp"
#include "hinf/runtime/prior_covariance.hpp"

namespace hinf::runtime {

template <class Model, class Measurement, class Policy>
class AugmentedEkf : public detail::KalmanCore<Model, Measurement> {
  using Core = detail::KalmanCore<Model, Measurement>;

 public:
  using typename Core::Input;
  using typename Core::MeasurementJacobian;
  using typename Core::ObsCov;
  using typename Core::Observation;
  using typename Core::State;
  using typename Core::StateCov;
  static_assert(Policy::NX == Core::NX && Policy::NZ == Core::NZ, "AugmentedEkf: policy dimensions differ");
  static_assert(!detail::HasNormalise<Model, State, StateCov>::value,
                "AugmentedEkf: models with a chart switch (normalise) are not supported");

  // Q (the filter's Q_d) symmetric PSD, R symmetric PD; throws std::invalid_argument otherwise.
  AugmentedEkf(const Model& model, const Measurement& measurement, const StateCov& Q, const ObsCov& R,
               const Policy& policy)
      : Core(model, measurement, Q, R, "AugmentedEkf"), policy_(policy) {}

  void init(const State& x0, const StateCov& P0) {
    Core::init(x0, P0);
    policy_.start(x0);
    stopped_ = false;
  }

  // One sample: the input u over [t_k, t_{k+1}) and the measurement y at t_{k+1}, (209).
  FilterStatus step(const Input& u, const Observation& y) {
    if (stopped_) return FilterStatus::Stopped;
    State x_next;
    StateCov F;
    FilterStatus s = this->evaluate_process(u, x_next, F);
    if (s != FilterStatus::Ok) return s;
    const StateCov FP = F * this->P_;
    StateCov PhiPPhiT;
    PhiPPhiT.noalias() = FP * F.transpose();
    const State x_prev = this->x_;
    const StateCov P_prev = this->P_;
    this->x_ = x_next;
    Observation y_pred;
    MeasurementJacobian H;
    s = this->evaluate_measurement(y, y_pred, H);
    if (s != FilterStatus::Ok) {  // no residual: the plain prediction, the update skipped (as Ekf)
      this->P_ = PhiPPhiT;
      this->P_ += this->Q_;
      detail::symmetrise(this->P_);
      return s;
    }
    const Observation residual = this->meas_.residual(y, y_pred);
    const FilterStatus fading = policy_.prior(PhiPPhiT, this->Q_, H, residual, this->R_, this->P_);
    detail::symmetrise(this->P_);
    const StateCov P_prior = this->P_;
    s = this->finish_update(y, y_pred, H, P_prior, this->R_);
    if (!this->x_.allFinite() || !this->P_.allFinite()) {
      stopped_ = true;
      return restore(x_prev, P_prev, FilterStatus::StateNotFinite);
    }
    if (s == FilterStatus::Ok) policy_.corrected(this->x_);
    return s != FilterStatus::Ok ? s : fading;
  }

  const Policy& policy() const { return policy_; }
  bool stopped() const { return stopped_; }

 private:
  FilterStatus restore(const State& x, const StateCov& P, FilterStatus s) {
    this->x_ = x;
    this->P_ = P;
    return s;
  }

  Policy policy_;
  bool stopped_ = false;
};

}  // namespace hinf::runtime
