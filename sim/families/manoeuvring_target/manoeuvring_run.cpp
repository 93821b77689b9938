// run_manoeuvring (manoeuvring_run.hpp): the truth and the stream once, then each filter over it.
#include "hinf/sim/manoeuvring_run.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <limits>

#include "hinf/models/lvlh.hpp"
#include "hinf/runtime/manoeuvre_estimator.hpp"
#include "hinf/sim/rng.hpp"

namespace hinf::sim {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// What every filter sees at t_k: the measurement mapped into LVLH0 and its covariance (k ≥ 1),
// the chaser's command over [t_k, t_{k+1}] in LVLH0, and the truth.
struct Stream {
  std::vector<ManoeuvringTruthSample> truth;
  std::vector<Eigen::Vector3d> y, u_chaser;
  std::vector<Eigen::Matrix3d> R;
  std::vector<double> range;
  models::OrbitState reference0;  // the chaser's navigated state at t0: the filters' reference orbit
  Vector6 x0;                     // X(t0|t0)
};

models::OrbitState navigated(const models::OrbitState& truth, const ManoeuvringScenario& s, Rng& rng) {
  models::OrbitState x = truth;
  if (!s.noise) return x;
  for (int i = 0; i < 3; ++i) x.r(i) += s.navigation_position_sigma * rng.normal();
  for (int i = 0; i < 3; ++i) x.v(i) += s.navigation_velocity_sigma * rng.normal();
  return x;
}

// (222): Z from the truth in LVLH1 (plus noise), z1 = h(Z), Y = T_m z1, R0 = T_m J R_Z Jᵀ T_mᵀ with
// T_m = I0ᵀ I1 from the navigated chaser and the filters' reference orbit.
Stream make_stream(const ManoeuvringScenario& s, const ManoeuvringEstimate& e, std::uint64_t seed) {
  Stream st;
  st.truth = manoeuvring_truth(s);
  Rng nav_rng(derive_seed(seed, 1)), meas_rng(derive_seed(seed, 2)), init_rng(derive_seed(seed, 3));
  const std::size_t n = st.truth.size();
  std::vector<models::OrbitState> nav(n);
  for (std::size_t k = 0; k < n; ++k) nav[k] = navigated(st.truth[k].chaser, s, nav_rng);
  st.reference0 = nav[0];
  const models::KeplerOrbit reference(st.reference0, s.mu);
  const models::RangeAzimuthElevation rae(Eigen::Matrix3d::Identity(), s.convention);
  st.y.resize(n);
  st.R.resize(n);
  st.range.resize(n);
  st.u_chaser.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const ManoeuvringTruthSample& x = st.truth[k];
    const Eigen::Matrix3d I0 = models::lvlh_to_inertial(reference.state(x.t));
    st.u_chaser[k] = I0.transpose() * thrust_inertial(s.chaser_manoeuvres, x.t, nav[k], I0);
    const Eigen::Vector3d d1 = models::lvlh_to_inertial(x.chaser).transpose() * (x.target.r - x.chaser.r);
    models::RangeAzimuthElevation::Vector Z = rae.rae_from_body(d1);
    if (s.noise)
      for (int i = 0; i < 3; ++i) Z(i) += s.measurement_sigma(i) * meas_rng.normal();
    const Eigen::Matrix3d Tm = I0.transpose() * models::lvlh_to_inertial(nav[k]);
    st.y[k] = Tm * rae.position_from_measurement(Z);
    st.R[k] = Tm * rae.position_covariance(Z, s.measurement_sigma(0), s.measurement_sigma(1), s.measurement_sigma(2)) *
              Tm.transpose();
    st.range[k] = d1.norm();
  }
  st.x0 = st.truth[0].relative;
  if (s.noise)
    for (int i = 0; i < 6; ++i) st.x0(i) += e.initial_error_sigma(i) * init_rng.normal();
  return st;
}

// Accumulates one window's metrics.
class WindowAccumulator {
 public:
  void add(const ManoeuvringSample& s) {
    const Vector6 err = s.estimate - s.truth;
    pos_sq_ += err.head<3>().cwiseAbs2();
    vel_sq_ += err.tail<3>().cwiseAbs2();
    pos_max_ = pos_max_.cwiseMax(err.head<3>().cwiseAbs());
    const Eigen::Vector3d e = s.u_hat - s.true_u;
    u_sum_ += e;
    u_sq_ += e.cwiseAbs2();
    u_max_ = u_max_.cwiseMax(e.cwiseAbs());
    var_paper_ += s.u_var_paper;
    var_innov_ += s.u_var_innovation;
    for (int i = 0; i < 3; ++i) {
      in_paper_(i) += std::abs(e(i)) <= 3 * std::sqrt(s.u_var_paper(i)) ? 1 : 0;
      in_innov_(i) += std::abs(e(i)) <= 3 * std::sqrt(s.u_var_innovation(i)) ? 1 : 0;
    }
    ++n_;
  }

  ManoeuvringWindowStatistics finish() const {
    ManoeuvringWindowStatistics w;
    w.samples = n_;
    const double n = static_cast<double>(n_);
    const Eigen::Vector3d nan = Eigen::Vector3d::Constant(kNaN);
    if (n_ == 0) {
      w.position_rms = w.velocity_rms = w.position_error_max = w.u_error_mean = w.u_error_rms = w.u_error_max = nan;
      w.u_sigma_paper = w.u_sigma_innovation = w.coverage_paper = w.coverage_innovation = nan;
      return w;
    }
    w.position_rms = (pos_sq_ / n).cwiseSqrt();
    w.velocity_rms = (vel_sq_ / n).cwiseSqrt();
    w.position_error_max = pos_max_;
    w.u_error_mean = u_sum_ / n;
    w.u_error_rms = (u_sq_ / n).cwiseSqrt();
    w.u_error_max = u_max_;
    w.u_sigma_paper = (var_paper_ / n).cwiseSqrt();
    w.u_sigma_innovation = (var_innov_ / n).cwiseSqrt();
    w.coverage_paper = in_paper_ / n;
    w.coverage_innovation = in_innov_ / n;
    return w;
  }

 private:
  Eigen::Vector3d pos_sq_ = Eigen::Vector3d::Zero(), vel_sq_ = Eigen::Vector3d::Zero(),
                  pos_max_ = Eigen::Vector3d::Zero(), u_sum_ = Eigen::Vector3d::Zero(),
                  u_sq_ = Eigen::Vector3d::Zero(), u_max_ = Eigen::Vector3d::Zero(),
                  var_paper_ = Eigen::Vector3d::Zero(), var_innov_ = Eigen::Vector3d::Zero(),
                  in_paper_ = Eigen::Vector3d::Zero(), in_innov_ = Eigen::Vector3d::Zero();
  long n_ = 0;
};

// Seconds from `from` until |Û − U| ≤ tol holds on every sample tagged in [t, to), per axis.
Eigen::Vector3d settle_time(const std::vector<ManoeuvringSample>& samples, double from, double to, double tol) {
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    double settled = kNaN;
    bool any = false;
    for (const ManoeuvringSample& s : samples) {
      if (s.u_time < from || s.u_time >= to) continue;
      any = true;
      const bool ok = std::abs(s.u_hat(i) - s.true_u(i)) <= tol;
      if (!ok) settled = kNaN;
      else if (std::isnan(settled)) settled = s.u_time - from;
    }
    out(i) = any ? settled : kNaN;
  }
  return out;
}

ManoeuvringFilterStatistics statistics(const ManoeuvringScenario& s, const ManoeuvringRunOptions& o,
                                       const ManoeuvreFilterSettings& f, const std::vector<ManoeuvringSample>& samples,
                                       long failed) {
  ManoeuvringFilterStatistics out;
  out.failed_steps = failed;
  for (const MetricWindow& w : o.windows) {
    WindowAccumulator acc;
    for (const ManoeuvringSample& x : samples)
      if (x.updated && w.start <= x.u_time && x.u_time < w.end) acc.add(x);
    out.windows.push_back(acc.finish());
  }
  out.settle_after_onset = out.settle_after_offset = Eigen::Vector3d::Constant(kNaN);
  out.detection_delay = out.false_alarm_rate = kNaN;
  if (!s.target_manoeuvres.empty()) {
    const ThrustArc& m = s.target_manoeuvres.front();
    out.settle_after_onset = settle_time(samples, m.start, m.end, o.maneuver_tolerance);
    out.settle_after_offset = settle_time(samples, m.end, s.duration, o.maneuver_tolerance);
    if (f.detector_window > 0) {
      long tests = 0, alarms = 0;
      for (const ManoeuvringSample& x : samples) {
        if (x.t <= m.start && x.tested) {
          ++tests;
          alarms += x.alarm ? 1 : 0;
        }
        if (x.t > m.start && x.alarm && std::isnan(out.detection_delay)) out.detection_delay = x.t - m.start;
      }
      if (tests > 0) out.false_alarm_rate = static_cast<double>(alarms) / static_cast<double>(tests);
    }
  }
  if (!samples.empty()) {
    const ManoeuvringSample& last = samples.back();
    out.final_position_error = (last.estimate - last.truth).head<3>().norm();
  }
  return out;
}

ManoeuvringFilterStatistics run_filter(const ManoeuvringScenario& s, const ManoeuvringRunOptions& o,
                                       const Stream& st, const ManoeuvreFilterSettings& f, int index) {
  runtime::ManoeuvreEstimatorSettings es;
  es.predict_with_chaser_control = f.predict_with_chaser_control;
  es.nis_window = f.detector_window;
  if (f.detector_window > 0) es.nis_threshold = nis_window_threshold(f.detector_window, f.detector_false_alarm);
  runtime::TransientManoeuvreEstimator filter(es);
  const Matrix6 P0 = o.estimate.sigma.cwiseAbs2().asDiagonal();
  filter.init(st.x0, P0);
  const models::EllipticRelativeModel model(models::KeplerOrbit(st.reference0, s.mu), f.model);
  std::vector<ManoeuvringSample> samples;
  samples.reserve(st.truth.size());
  long failed = 0;
  for (std::size_t k = 0; k + 1 < st.truth.size(); ++k) {
    const double t = st.truth[k].t;
    const models::SampledRelativeStep m = model.step(t, s.sample_time, f.predict_with_chaser_control);
    const runtime::FilterStatus status =
        filter.step(m.Phi, m.Qd, m.Gamma, st.y[k + 1], st.R[k + 1], st.u_chaser[k], s.sample_time);
    ManoeuvringSample x;
    x.updated = status == runtime::FilterStatus::Ok;
    if (!x.updated) ++failed;
    x.t = st.truth[k + 1].t;
    x.u_time = t;
    x.truth = st.truth[k + 1].relative;
    x.estimate = filter.x();
    x.sigma = filter.P().diagonal().cwiseSqrt();
    x.measured_position = st.y[k + 1];
    x.true_u = st.truth[k].target_accel;
    x.u_hat = filter.manoeuvre();
    x.u_var_paper = filter.manoeuvre_covariance_paper().diagonal();
    x.u_var_innovation = filter.manoeuvre_covariance_innovation().diagonal();
    x.u_chaser = st.u_chaser[k];
    x.nis = filter.nis();
    x.window_nis = filter.window_nis();
    x.tested = filter.window_full();
    x.alarm = filter.alarm();
    x.range = st.range[k + 1];
    if (o.on_sample) o.on_sample(index, x);
    samples.push_back(x);
  }
  return statistics(s, o, f, samples, failed);
}

}  // namespace

double nis_window_threshold(int window, double p_false_alarm) {
  const boost::math::chi_squared chi2(3.0 * window);
  return boost::math::quantile(boost::math::complement(chi2, p_false_alarm));
}

std::vector<ManoeuvringFilterStatistics> run_manoeuvring(const ManoeuvringScenario& s,
                                                         const std::vector<ManoeuvreFilterSettings>& filters,
                                                         const ManoeuvringRunOptions& o, std::uint64_t seed) {
  const Stream stream = make_stream(s, o.estimate, seed);
  std::vector<ManoeuvringFilterStatistics> out;
  for (std::size_t f = 0; f < filters.size(); ++f) out.push_back(run_filter(s, o, stream, filters[f], static_cast<int>(f)));
  return out;
}

}  // namespace hinf::sim
