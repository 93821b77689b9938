// What the EKF and the REKF share (docs/maths.md §12–§13): the model and measurement, the
// state x, covariances P, P0, Q, R, the last update's S, K and innovation, the NIS gate and
// the covariance policy, their configuration and accessors, and the two halves of a step:
//     predict:  x ← f(x, u),  P ← F P̄ Fᵀ (+ extra) + Q             (symmetrised)
//     update:   ν = residual(y, h(x)),  Joseph update from P̄ with R̄  (joseph_update.hpp)
// where the EKF passes P̄ = P, R̄ = R and the REKF P̄ = M(P), R̄ = γ²CCᵀ + R, extra = γ²AAᵀ.
// Fixed sizes throughout: no heap allocation in a step.
//
// Manifold hooks (docs/maths.md (194), (195)). A model whose state is not a vector space may
// provide either or both of
//   State boxplus(const State& x, const State& dx) const;   the correction x ⊞ K ν
//   void normalise(State& x, StateCov& P) const;            a chart switch after every step
// (the state x then carries the estimate, P the covariance of its error Δx). Without them the
// code is the additive update, unchanged: x ← x + K ν computed as before, bit for bit.
//
// A model whose state has more coordinates than its error (a unit quaternion: 4 numbers, 3
// error angles) declares `static constexpr int NS` beside NX: x is then NS × 1, P, F, H and
// K are sized by NX, and boxplus (x, Δx of size NX) is required. Without NS, NS = NX.
#pragma once

#include <Eigen/Dense>

#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "hinf/runtime/detail/covariance.hpp"
#include "hinf/runtime/detail/joseph_update.hpp"
#include "hinf/runtime/filter_status.hpp"

namespace hinf::runtime::detail {

template <class Model, class State, class Error, class = void>
struct HasBoxplus : std::false_type {};
template <class Model, class State, class Error>
struct HasBoxplus<Model, State, Error,
                  std::void_t<decltype(std::declval<const Model&>().boxplus(std::declval<const State&>(),
                                                                            std::declval<const Error&>()))>>
    : std::true_type {};

// NS of the model if it declares one, else NX.
template <class Model, class = void>
struct StateDimension : std::integral_constant<int, Model::NX> {};
template <class Model>
struct StateDimension<Model, std::void_t<decltype(Model::NS)>> : std::integral_constant<int, Model::NS> {};

template <class Model, class State, class Cov, class = void>
struct HasNormalise : std::false_type {};
template <class Model, class State, class Cov>
struct HasNormalise<Model, State, Cov,
                    std::void_t<decltype(std::declval<const Model&>().normalise(std::declval<State&>(),
                                                                                std::declval<Cov&>()))>>
    : std::true_type {};

template <class Model, class Measurement>
class KalmanCore {
 public:
  static constexpr int NX = Model::NX;
  static constexpr int NS = StateDimension<Model>::value;
  static constexpr int NU = Model::NU;
  static constexpr int NZ = Measurement::NZ;
  // Eigen::Dynamic sizes (the linear model from Python) take their dimensions from Q and R.
  static constexpr bool kDynamic = NX == Eigen::Dynamic;
  static_assert((NX > 0 || kDynamic) && (NU > 0 || NU == Eigen::Dynamic) && (NZ > 0 || NZ == Eigen::Dynamic),
                "Kalman filter: dimensions must be positive (or Eigen::Dynamic)");
  static_assert(!kDynamic || NS == NX, "Kalman filter: a dynamic-size state has no manifold part");
  static_assert(Measurement::NX == Model::NX, "Kalman filter: model and measurement state dimensions differ");
  static_assert(NS == NX || HasBoxplus<Model, Eigen::Matrix<double, NS, 1>, Eigen::Matrix<double, NX, 1>>::value,
                "Kalman filter: a model with NS != NX must provide boxplus(x, dx)");

  using State = Eigen::Matrix<double, NS, 1>;
  using ErrorState = Eigen::Matrix<double, NX, 1>;
  using Input = Eigen::Matrix<double, NU, 1>;
  using Observation = Eigen::Matrix<double, NZ, 1>;
  using StateCov = Eigen::Matrix<double, NX, NX>;
  using ObsCov = Eigen::Matrix<double, NZ, NZ>;
  using Gain = Eigen::Matrix<double, NX, NZ>;
  using MeasurementJacobian = Eigen::Matrix<double, NZ, NX>;

  // x(0) and P(0); P0 (symmetric PD, else std::invalid_argument) is also the reset value.
  void init(const State& x0, const StateCov& P0) {
    require_size(x0.rows(), x0.cols(), "x0", x_.rows(), 1);
    require_size(P0.rows(), P0.cols(), "P0", P_.rows(), P_.cols());
    if (!x0.allFinite()) throw std::invalid_argument(std::string(name_) + ": x0 has a non-finite entry");
    require_positive_definite(P0, name_, "P0");
    x_ = x0;
    P0_ = 0.5 * (P0 + P0.transpose());
    P_ = P0_;
  }

  // Configuration.
  void set_Q(const StateCov& Q) {
    if (Q_.size() > 0) require_size(Q.rows(), Q.cols(), "Q", Q_.rows(), Q_.cols());
    require_positive_semidefinite(Q, name_, "Q");
    Q_ = 0.5 * (Q + Q.transpose());
  }
  void set_R(const ObsCov& R) {
    if (R_.size() > 0) require_size(R.rows(), R.cols(), "R", R_.rows(), R_.cols());
    require_positive_definite(R, name_, "R");
    R_ = 0.5 * (R + R.transpose());
  }
  void set_covariance_policy(CovariancePolicy p) { policy_ = p; }
  // Reject updates whose NIS exceeds the threshold (e.g. a chi-square quantile with NZ
  // degrees of freedom). Default +infinity: no gating.
  void set_innovation_gate(double nis_threshold) { nis_gate_ = nis_threshold; }
  // Overwrite the state (e.g. after an external reset); P is not checked here.
  void set_state(const State& x, const StateCov& P) {
    x_ = x;
    P_ = P;
  }

  const State& x() const { return x_; }
  const StateCov& P() const { return P_; }
  const StateCov& P0() const { return P0_; }
  const StateCov& Q() const { return Q_; }
  const ObsCov& R() const { return R_; }
  const Gain& K() const { return K_; }             // gain of the last successful update
  const ObsCov& S() const { return S_; }           // innovation covariance of the last update
  const Observation& innovation() const { return nu_; }
  double nis() const { return nis_; }              // nu^T S^-1 nu of the last update
  const Model& model() const { return model_; }
  const Measurement& measurement() const { return meas_; }
  // For models with a time-varying context (e.g. the epoch's frames) set between steps.
  Model& mutable_model() { return model_; }
  Measurement& mutable_measurement() { return meas_; }

 protected:
  // Q PSD, R PD; throws std::invalid_argument naming `name` otherwise.
  KalmanCore(const Model& model, const Measurement& measurement, const StateCov& Q, const ObsCov& R,
             const char* name)
      : model_(model), meas_(measurement), name_(name) {
    set_Q(Q);
    set_R(R);
    const Eigen::Index nx = Q_.rows(), nz = R_.rows();
    if constexpr (kDynamic) x_.setZero(nx);
    else x_.setZero();
    P_.setIdentity(nx, nx);
    P0_.setIdentity(nx, nx);
    K_.setZero(nx, nz);
    S_.setZero(nz, nz);
    nu_.setZero(nz);
  }

  // Dynamic sizes: a matrix given must have the filter's size (fixed sizes: the type says so).
  void require_size(Eigen::Index rows, Eigen::Index cols, const char* what, Eigen::Index want_rows,
                    Eigen::Index want_cols) const {
    if (rows != want_rows || cols != want_cols)
      throw std::invalid_argument(std::string(name_) + ": " + what + " must be " + std::to_string(want_rows) + "x" +
                                  std::to_string(want_cols) + ", got " + std::to_string(rows) + "x" +
                                  std::to_string(cols));
  }

  // f(x, u) and its Jacobian F; Ok, or why the step cannot be taken.
  FilterStatus evaluate_process(const Input& u, State& x_next, StateCov& F) const {
    if (!all_finite(u)) return FilterStatus::NonFiniteInput;
    x_next = model_.f(x_, u);
    F = model_.F(x_, u);
    if (!all_finite(x_next) || !all_finite(F)) return FilterStatus::ModelNotFinite;
    return FilterStatus::Ok;
  }

  // x ← x_next, P ← F P̄ Fᵀ (+ extra) + Q, symmetrised, then the covariance policy.
  FilterStatus finish_predict(const State& x_next, const StateCov& F, const StateCov& Pbar, const StateCov* extra) {
    const StateCov FP = F * Pbar;
    P_.noalias() = FP * F.transpose();
    if (extra) P_ += *extra;
    P_ += Q_;
    symmetrise(P_);
    x_ = x_next;
    normalise();
    return apply_covariance_policy<NX>(P_, P0_, policy_);
  }

  // h(x) and its Jacobian H; Ok, or why the update cannot be taken.
  FilterStatus evaluate_measurement(const Observation& y, Observation& y_pred, MeasurementJacobian& H) const {
    if (!all_finite(y)) return FilterStatus::NonFiniteInput;
    y_pred = meas_.h(x_);
    H = meas_.H(x_);
    if (!all_finite(y_pred) || !all_finite(H)) return FilterStatus::ModelNotFinite;
    return FilterStatus::Ok;
  }

  // ν = residual(y, y_pred), the Joseph update from P̄ with R̄, then the covariance policy.
  FilterStatus finish_update(const Observation& y, const Observation& y_pred, const MeasurementJacobian& H,
                             const StateCov& Pbar, const ObsCov& Rbar) {
    nu_ = meas_.residual(y, y_pred);
    const FilterStatus s = joseph_update<NX, NZ>(x_, P_, Pbar, H, Rbar, nu_, nis_gate_, nis_, S_, K_,
                                                 [this](State& x, const Gain& K, const Observation& nu) {
                                                   if constexpr (HasBoxplus<Model, State, ErrorState>::value) {
                                                     const ErrorState dx = K * nu;
                                                     x = model_.boxplus(x, dx);
                                                   } else {
                                                     (void)model_;  // `this` is captured for boxplus only
                                                     x.noalias() += K * nu;
                                                   }
                                                 });
    if (s != FilterStatus::Ok) return s;
    normalise();
    return apply_covariance_policy<NX>(P_, P0_, policy_);
  }

  void normalise() {
    if constexpr (HasNormalise<Model, State, StateCov>::value) model_.normalise(x_, P_);
  }

  Model model_;
  Measurement meas_;
  const char* name_;
  State x_;
  StateCov P_, P0_, Q_;
  ObsCov R_, S_;
  Gain K_;
  Observation nu_;
  double nis_ = 0.0;
  double nis_gate_ = std::numeric_limits<double>::infinity();
  CovariancePolicy policy_ = CovariancePolicy::Report;
};

}  // namespace hinf::runtime::detail
