// How the augmented EKF forms its prior covariance P⁻ from ΦPΦᵀ (docs/maths.md §31.4, (209)):
// the policies Plain (the AEKF), AdaptiveQ (the AAEKF, (210)) and StrongTracking (the
// ASTEKF, (211)). Each is a type with
//   static constexpr int NX, NZ;
//   void start(const State& x0);                         at init()
//   FilterStatus prior(const StateCov& PhiPPhiT, const StateCov& Q, const H&, const Observation& γ,
//                      const ObsCov& R, StateCov& P_minus);   P⁻ before the update
//   void corrected(const State& x);                       after every update
// `Q` is the filter's Q_d; a policy may replace it. The constructors allocate (the window of
// AdaptiveQ); prior() and corrected() do not. Eigen only.
#pragma once
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "hinf/runtime/filter_status.hpp"

namespace hinf::runtime {

// P⁻ = ΦPΦᵀ + Q_d: the plain EKF.
template <int NX_, int NZ_>
struct PlainPrior {
  static constexpr int NX = NX_, NZ = NZ_;
  using StateCov = Eigen::Matrix<double, NX, NX>;

  template <class State>
  void start(const State&) {}
  template <class H, class Obs, class ObsCov>
  FilterStatus prior(const StateCov& PhiPPhiT, const StateCov& Q, const H&, const Obs&, const ObsCov&,
                     StateCov& P_minus) {
    P_minus = PhiPPhiT;
    P_minus += Q;
    return FilterStatus::Ok;
  }
  template <class State>
  void corrected(const State&) {}
};

// (210): `Outer` F(κ) = κκᵀ (the literal reading), `Diagonal` F(κ) = diag(κ_i²).
enum class AdaptiveQLaw { Diagonal, Outer };

struct AdaptiveQSettings {
  int state_offset = 0;   // first entry of the augmented state β in x
  int error_offset = 0;   // first entry of δβ in δx (and of its block in Q_d)
  double sample_time = 1; // Δt, s
  int window = 30;        // m, steps
  double scale = 1;       // s
  double epsilon = 3;     // ε, s^½ (the source's compression factor)
  double floor = 0;       // Q_floor, added on the diagonal
  double initial = 0;     // Q_initial (× I), used until m corrections have been made
  AdaptiveQLaw law = AdaptiveQLaw::Diagonal;

  // Throws std::invalid_argument naming the field.
  void validate() const {
    if (state_offset < 0 || error_offset < 0) throw std::invalid_argument("AdaptiveQ: offsets must be >= 0");
    if (!(sample_time > 0) || !std::isfinite(sample_time)) throw std::invalid_argument("AdaptiveQ: sample_time must be > 0");
    if (window < 1) throw std::invalid_argument("AdaptiveQ: window must be >= 1");
    for (const double v : {scale, epsilon, floor, initial})
      if (!(v >= 0) || !std::isfinite(v))
        throw std::invalid_argument("AdaptiveQ: scale, epsilon, floor and initial must be finite and >= 0");
  }
};

// The AAEKF: the random-walk intensity Q_T of the NB augmented states follows the rate of
// change of their estimate over the last m corrections, (210); Q_d's block is Δt Q_T.
template <int NX_, int NZ_, int NB>
class AdaptiveQ {
 public:
  static constexpr int NX = NX_, NZ = NZ_;
  using StateCov = Eigen::Matrix<double, NX, NX>;
  using Block = Eigen::Matrix<double, NB, NB>;
  using Augmented = Eigen::Matrix<double, NB, 1>;

  explicit AdaptiveQ(const AdaptiveQSettings& s) : s_((s.validate(), s)), history_(static_cast<std::size_t>(s.window) + 1) {
    if (s.error_offset + NB > NX) throw std::invalid_argument("AdaptiveQ: error_offset + NB exceeds NX");
    reset_intensity();
  }

  template <class State>
  void start(const State& x0) {
    if (s_.state_offset + NB > x0.size()) throw std::invalid_argument("AdaptiveQ: state_offset + NB exceeds NS");
    count_ = 0;
    reset_intensity();
    record(x0);
  }

  template <class H, class Obs, class ObsCov>
  FilterStatus prior(const StateCov& PhiPPhiT, const StateCov& Q, const H&, const Obs&, const ObsCov&,
                     StateCov& P_minus) {
    StateCov Qd = Q;
    Qd.template block<NB, NB>(s_.error_offset, s_.error_offset) = Q_T_ * s_.sample_time;
    P_minus = PhiPPhiT;
    P_minus += Qd;
    return FilterStatus::Ok;
  }

  // Records β̂_k; from the m-th correction on, Q_T = s ε² F(κ) + Q_floor I with
  // κ = (β̂_k − β̂_{k−m}) / (m Δt).
  template <class State>
  void corrected(const State& x) {
    record(x);
    if (count_ <= s_.window) return;
    const Augmented& newest = history_[slot(count_ - 1)];
    const Augmented& oldest = history_[slot(count_ - 1 - s_.window)];
    kappa_ = (newest - oldest) / (s_.window * s_.sample_time);
    Q_T_ = law_matrix(kappa_) * (s_.scale * s_.epsilon * s_.epsilon);
    Q_T_.diagonal().array() += s_.floor;
  }

  // F(κ) of (210).
  Block law_matrix(const Augmented& kappa) const {
    if (s_.law == AdaptiveQLaw::Outer) return kappa * kappa.transpose();
    return Block(kappa.array().square().matrix().asDiagonal());
  }

  const Block& intensity() const { return Q_T_; }  // Q_T for the next prediction, (N m)²/s
  const Augmented& rate() const { return kappa_; }  // κ of the last adaptation
  const AdaptiveQSettings& settings() const { return s_; }

 private:
  template <class State>
  void record(const State& x) {
    history_[slot(count_)] = x.template segment<NB>(s_.state_offset);
    ++count_;
  }
  std::size_t slot(long k) const { return static_cast<std::size_t>(k % static_cast<long>(history_.size())); }
  void reset_intensity() {
    Q_T_ = Block::Identity() * s_.initial;
    kappa_.setZero();
  }

  AdaptiveQSettings s_;
  std::vector<Augmented> history_;  // ring of the last m + 1 estimates (sized in the constructor)
  long count_ = 0;                  // estimates recorded (β̂_0 and one per correction)
  Block Q_T_;
  Augmented kappa_;
};

enum class FadingForm { Symmetric, LiteralSymmetrised };

template <int NX>
struct StrongTrackingSettings {
  double forgetting = 0.95;  // ρ ∈ (0, 1]
  double weakening = 1;      // K_b ≥ 1
  Eigen::Matrix<double, NX, 1> alpha = Eigen::Matrix<double, NX, 1>::Ones();  // α_i ≥ 1
  double lambda_max = 1e3;   // cap on every λ_i, ≥ 1
  FadingForm form = FadingForm::Symmetric;

  // Throws std::invalid_argument naming the field.
  void validate() const {
    if (!(forgetting > 0 && forgetting <= 1)) throw std::invalid_argument("StrongTracking: forgetting must be in (0, 1]");
    if (!(weakening >= 1) || !std::isfinite(weakening)) throw std::invalid_argument("StrongTracking: weakening must be >= 1");
    if (!alpha.allFinite() || alpha.minCoeff() < 1) throw std::invalid_argument("StrongTracking: every alpha must be >= 1");
    if (!(lambda_max >= 1) || std::isnan(lambda_max)) throw std::invalid_argument("StrongTracking: lambda_max must be >= 1");
  }
};

// The ASTEKF's multiple fading factors, (211).
template <int NX_, int NZ_>
class StrongTracking {
 public:
  static constexpr int NX = NX_, NZ = NZ_;
  using StateCov = Eigen::Matrix<double, NX, NX>;
  using Factors = Eigen::Matrix<double, NX, 1>;
  using ObsCov = Eigen::Matrix<double, NZ, NZ>;

  explicit StrongTracking(const StrongTrackingSettings<NX>& s) : s_((s.validate(), s)) { start(0); }

  template <class State>
  void start(const State&) {
    steps_ = 0;
    cap_hits_ = 0;
    guard_hits_ = 0;
    V0_.setZero();
    lambda_.setOnes();
    c_ = 1;
  }

  template <class H, class Obs>
  FilterStatus prior(const StateCov& PhiPPhiT, const StateCov& Q, const H& Hk, const Obs& gamma, const ObsCov& R,
                     StateCov& P_minus) {
    const FilterStatus s = fading_factors(PhiPPhiT, Q, Hk, gamma, R);
    if (s_.form == FadingForm::Symmetric) {
      P_minus = PhiPPhiT;
      for (int j = 0; j < NX; ++j)
        for (int i = 0; i < NX; ++i) P_minus(i, j) *= std::sqrt(lambda_(i) * lambda_(j));
    } else {
      P_minus = lambda_.asDiagonal() * PhiPPhiT;
      P_minus = 0.5 * (P_minus + P_minus.transpose()).eval();
    }
    P_minus += Q;
    return s;
  }

  // V₀, c and λ of (211) from this step's residual; returns FadingFactorCapped,
  // FadingTraceGuard or Ok.
  template <class H, class Obs>
  FilterStatus fading_factors(const StateCov& PhiPPhiT, const StateCov& Q, const H& Hk, const Obs& gamma,
                              const ObsCov& R) {
    const ObsCov gg = gamma * gamma.transpose();
    V0_ = steps_ == 0 ? gg : ((s_.forgetting * V0_ + gg) / (1 + s_.forgetting)).eval();
    ++steps_;
    const ObsCov N = V0_ - s_.weakening * R - Hk * Q * Hk.transpose();
    const StateCov HtH = Hk.transpose() * Hk;
    double denominator = 0;
    for (int i = 0; i < NX; ++i) denominator += s_.alpha(i) * PhiPPhiT.row(i).dot(HtH.col(i));
    lambda_.setOnes();
    if (!(denominator > 0) || !std::isfinite(denominator)) {
      ++guard_hits_;
      c_ = 1;
      return FilterStatus::FadingTraceGuard;
    }
    c_ = N.trace() / denominator;
    bool capped = false;
    for (int i = 0; i < NX; ++i) {
      const double l = s_.alpha(i) * c_;
      if (l > 1) lambda_(i) = l;
      if (lambda_(i) > s_.lambda_max) {
        lambda_(i) = s_.lambda_max;
        capped = true;
      }
    }
    if (!capped) return FilterStatus::Ok;
    ++cap_hits_;
    return FilterStatus::FadingFactorCapped;
  }

  template <class State>
  void corrected(const State&) {}

  const Factors& lambda() const { return lambda_; }  // λ of the last step
  double c() const { return c_; }
  const ObsCov& V0() const { return V0_; }
  long cap_hits() const { return cap_hits_; }      // steps where some λ_i reached λ_max
  long guard_hits() const { return guard_hits_; }  // steps with Σ α_i M_ii ≤ 0
  const StrongTrackingSettings<NX>& settings() const { return s_; }

 private:
  StrongTrackingSettings<NX> s_;
  ObsCov V0_;
  Factors lambda_;
  double c_ = 1;
  long steps_ = 0, cap_hits_ = 0, guard_hits_ = 0;
};

}  // namespace hinf::runtime
