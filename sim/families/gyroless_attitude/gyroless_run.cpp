// run_gyroless (gyroless_run.hpp): the truth and the stream once, then each filter over it.
#include "hinf/sim/gyroless_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hinf/models/star_tracker.hpp"
#include "hinf/runtime/augmented_ekf.hpp"
#include "hinf/sim/metrics.hpp"
#include "hinf/sim/rng.hpp"
#include "hinf/sim/simulation_error.hpp"

namespace hinf::sim {

namespace {

using Process = models::RigidBodyAttitudeProcess;
using StarTracker = models::StarTrackerMeasurement<2>;
using State = Process::State;
using Error = Process::Error;
using Cov = Eigen::Matrix<double, 9, 9>;
using Obs = StarTracker::Vector;
namespace ix = models::rigid_body_index;

constexpr double kDegreesPerRadian = 1 / models::kRadiansPerDegree;

Process filter_process(const GyrolessScenario& s, const GyrolessInitialEstimate& e) {
  models::RigidBodyParameters p;
  p.inertia = s.inertia;
  p.wheel_momentum = s.wheel_momentum;
  p.sample_time = s.sample_time;
  p.substeps = e.prediction_substeps;
  return Process(p);
}

// What every filter sees: the truth at t_k and the star-tracker vectors at t_k (k ≥ 1).
struct Stream {
  std::vector<State> truth;
  std::vector<Obs> z;  // z[k] at t_k; z[0] unused
};

Stream make_stream(const GyrolessScenario& s, std::uint64_t seed) {
  Stream st{gyroless_truth(s), {}};
  const StarTracker tracker(s.reference_vectors);
  Rng rng(derive_seed(seed, 2));
  const double sigma = std::sqrt(s.star_tracker_variance);
  st.z.resize(st.truth.size());
  for (std::size_t k = 1; k < st.truth.size(); ++k) {
    st.z[k] = tracker.h(st.truth[k]);
    for (int i = 0; i < StarTracker::NZ; ++i) st.z[k](i) += sigma * rng.normal();
  }
  return st;
}

// x̂(0) and P0 (docs/experiments.md "Seed 002"): as given, or the given estimate ⊞ a draw of N(0, P0).
State initial_estimate(const Process& model, const GyrolessInitialEstimate& e, const Cov& P0, std::uint64_t seed) {
  State x;
  x << e.q0.normalized(), e.w0, e.torque0;
  if (!e.sample) return x;
  Rng rng(derive_seed(seed, 3));
  Error d;
  for (int i = 0; i < 9; ++i) d(i) = std::sqrt(P0(i, i)) * rng.normal();
  return model.boxplus(x, d);
}

Cov initial_covariance(const GyrolessInitialEstimate& e) {
  Eigen::Matrix<double, 9, 1> s;
  s << Eigen::Vector3d::Constant(e.sigma_attitude), Eigen::Vector3d::Constant(e.sigma_rate),
      Eigen::Vector3d::Constant(e.sigma_torque);
  return s.array().square().matrix().asDiagonal();
}

// Pearson correlation of two equally long series (0 if either is constant).
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  if (a.size() < 2) return 0;
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= n, mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0;
}

// The window accumulators of one filter.
class WindowStatistics {
 public:
  void add(const GyrolessSample& s) {
    const Eigen::Vector3d att = s.error.segment<3>(ix::kAttitudeError) * kDegreesPerRadian;
    const Eigen::Vector3d tq = s.error.segment<3>(ix::kTorqueError);
    att_sq_ += att.cwiseAbs2();
    tq_sq_ += tq.cwiseAbs2();
    att_max_ = std::max(att_max_, att.norm());
    tq_norm_.push_back(tq.norm());
    rate_norm_.push_back(s.torque_rate.norm());
    for (int i = 0; i < 3; ++i) {
      tq_abs_[i].push_back(std::abs(tq(i)));
      rate_abs_[i].push_back(std::abs(s.torque_rate(i)));
    }
    nees_ += s.nees;
    ++n_;
  }

  void finish(GyrolessFilterStatistics& out) const {
    if (n_ == 0) return;
    out.attitude_rms_deg = (att_sq_ / n_).cwiseSqrt();
    out.torque_rms = (tq_sq_ / n_).cwiseSqrt();
    out.attitude_rms_norm_deg = out.attitude_rms_deg.norm();
    out.torque_rms_norm = out.torque_rms.norm();
    out.attitude_max_deg = att_max_;
    out.torque_p95 = nearest_rank_quantile(tq_norm_, 0.95);
    for (int i = 0; i < 3; ++i) out.torque_rate_correlation(i) = correlation(tq_abs_[i], rate_abs_[i]);
    out.torque_rate_correlation_norm = correlation(tq_norm_, rate_norm_);
    out.nees_mean = nees_ / n_;
  }

 private:
  Eigen::Vector3d att_sq_ = Eigen::Vector3d::Zero(), tq_sq_ = Eigen::Vector3d::Zero();
  double att_max_ = 0, nees_ = 0;
  long n_ = 0;
  std::vector<double> tq_norm_, rate_norm_, tq_abs_[3], rate_abs_[3];
};

// What a policy reports into a sample: the Q_T it will use, its fading factors.
Eigen::Vector3d q_torque_of(const runtime::PlainPrior<9, 6>&, double Q) { return Eigen::Vector3d::Constant(Q); }
Eigen::Vector3d q_torque_of(const runtime::StrongTracking<9, 6>&, double Q) { return Eigen::Vector3d::Constant(Q); }
Eigen::Vector3d q_torque_of(const runtime::AdaptiveQ<9, 6, 3>& p, double) { return p.intensity().diagonal(); }
Eigen::Matrix<double, 9, 1> lambda_of(const runtime::StrongTracking<9, 6>& p) { return p.lambda(); }
template <class Policy>
Eigen::Matrix<double, 9, 1> lambda_of(const Policy&) {
  return Eigen::Matrix<double, 9, 1>::Ones();
}
long cap_hits_of(const runtime::StrongTracking<9, 6>& p) { return p.cap_hits(); }
template <class Policy>
long cap_hits_of(const Policy&) {
  return 0;
}

template <class Policy>
GyrolessFilterStatistics run_filter(const GyrolessScenario& s, const GyrolessRunOptions& o, const Stream& stream,
                                    double Q, const Policy& policy, std::uint64_t seed, int index) {
  const Process model = filter_process(s, o.estimate);
  const Cov P0 = initial_covariance(o.estimate);
  runtime::AugmentedEkf<Process, StarTracker, Policy> filter(
      model, StarTracker(s.reference_vectors), model.discrete_process_noise(Q),
      Eigen::Matrix<double, StarTracker::NZ, StarTracker::NZ>::Identity() * s.star_tracker_variance, policy);
  filter.init(initial_estimate(model, o.estimate, P0, seed), P0);
  GyrolessFilterStatistics out;
  WindowStatistics window;
  for (std::size_t k = 1; k < stream.truth.size(); ++k) {
    GyrolessSample sample;
    sample.q_torque = q_torque_of(filter.policy(), Q);
    const runtime::FilterStatus status = filter.step(Eigen::Vector3d::Zero(), stream.z[k]);
    ++out.steps;
    if (status == runtime::FilterStatus::StateNotFinite) out.stopped = true;
    if (status != runtime::FilterStatus::Ok && status != runtime::FilterStatus::FadingFactorCapped) ++out.failed_steps;
    sample.t = static_cast<double>(k) * s.sample_time;
    sample.truth = stream.truth[k];
    sample.estimate = filter.x();
    sample.torque_rate = s.torque_rate(sample.t);
    sample.error = Process::difference(sample.truth, sample.estimate);
    sample.sigma = filter.P().diagonal().cwiseSqrt();
    sample.lambda = lambda_of(filter.policy());
    sample.nees = sample.error.dot(filter.P().llt().solve(sample.error));
    if (o.on_sample) o.on_sample(index, sample);
    if (sample.t >= o.window_start) window.add(sample);
  }
  window.finish(out);
  out.lambda_cap_hits = cap_hits_of(filter.policy());
  if (out.stopped) {  // a stopped filter has no statistics
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.attitude_rms_norm_deg = out.torque_rms_norm = out.torque_p95 = out.attitude_max_deg = out.nees_mean = nan;
  }
  return out;
}

}  // namespace

std::vector<State> gyroless_truth(const GyrolessScenario& s) {
  models::RigidBodyParameters p;
  p.inertia = s.inertia;
  p.wheel_momentum = s.wheel_momentum;
  const models::RigidBodyDynamics dyn(p);
  const long n = std::lround(s.duration / s.sample_time);
  const double h = s.sample_time / s.truth_substeps;
  std::vector<State> truth;
  truth.reserve(static_cast<std::size_t>(n) + 1);
  Eigen::Matrix<double, 7, 1> y;
  y << s.q0.normalized(), s.w0;
  for (long k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) * s.sample_time;
    State x;
    x << y, s.torque(t);
    require_finite_truth("gyroless_attitude", k, t, x,
                         {{"attitude quaternion q", ix::kQuaternion, 4},
                          {"body rate omega (rad/s)", ix::kRate, 3},
                          {"disturbance torque (N m)", ix::kTorque, 3}});
    truth.push_back(x);
    if (k == n) break;
    for (int j = 0; j < s.truth_substeps; ++j) {
      const double t0 = t + j * h;
      y = dyn.rk4(y, h, [&](double tau) { return s.torque(t0 + tau); });
    }
  }
  return truth;
}

std::vector<GyrolessFilterStatistics> run_gyroless(const GyrolessScenario& s,
                                                   const std::vector<GyrolessFilterSettings>& filters,
                                                   const GyrolessRunOptions& o, std::uint64_t seed) {
  const Stream stream = make_stream(s, seed);
  std::vector<GyrolessFilterStatistics> out;
  for (std::size_t f = 0; f < filters.size(); ++f) {
    const GyrolessFilterSettings& fs = filters[f];
    const int index = static_cast<int>(f);
    switch (fs.kind) {
      case GyrolessFilterKind::Aekf:
        out.push_back(run_filter(s, o, stream, fs.Q, runtime::PlainPrior<9, 6>{}, seed, index));
        break;
      case GyrolessFilterKind::Astekf:
        out.push_back(run_filter(s, o, stream, fs.Q, runtime::StrongTracking<9, 6>(fs.strong_tracking), seed, index));
        break;
      case GyrolessFilterKind::Aaekf: {
        runtime::AdaptiveQSettings a = fs.adaptive;
        a.state_offset = ix::kTorque;
        a.error_offset = ix::kTorqueError;
        a.sample_time = s.sample_time;
        out.push_back(run_filter(s, o, stream, a.initial, runtime::AdaptiveQ<9, 6, 3>(a), seed, index));
        break;
      }
    }
  }
  return out;
}

}  // namespace hinf::sim
