// run_gps_ins (gps_ins_run.hpp): docs/maths.md §29–§30.
#include "hinf/sim/gps_ins_run.hpp"

#include <cmath>
#include <optional>

#include "hinf/runtime/ekf.hpp"
#include "hinf/runtime/rekf.hpp"
#include "hinf/sim/gps_ins_truth.hpp"
#include "hinf/sim/rng.hpp"

namespace hinf::sim {

namespace {

using models::GpsInsMeasurement;
using models::GpsInsProcess;
using State = GpsInsProcess::State;
using Mat15 = GpsInsProcess::Jacobian;
constexpr int NZ = GpsInsMeasurement::NZ;
using ObsCov = Eigen::Matrix<double, NZ, NZ>;
namespace ix = models::gps_ins_index;

constexpr double kDivergedPositionError = 10.0;  // m, after kDivergenceCheckStart
constexpr double kDivergenceCheckStart = 2000.0;  // s

State initial_sigma(const GpsInsInitialError& e) {
  State s;
  s << Eigen::Vector3d::Constant(e.position), Eigen::Vector3d::Constant(e.velocity),
      Eigen::Vector3d::Constant(e.attitude / 4),  // MRP units: one unit is 4 rad (docs/maths.md (179))
      Eigen::Vector3d::Constant(e.rate), Eigen::Vector3d::Constant(e.bias);
  return s;
}

ObsCov measurement_covariance(const GpsInsScenario& s) {
  ObsCov R = ObsCov::Zero();
  R.diagonal().head<3>().setConstant(s.gyro_noise_sigma * s.gyro_noise_sigma);
  R.diagonal().segment<models::kGpsInsSatellites>(GpsInsMeasurement::kPseudorangeRow)
      .setConstant(s.pseudorange_sigma * s.pseudorange_sigma);
  R.diagonal().tail<NZ - GpsInsMeasurement::kPhaseRow>().setConstant(s.phase_sigma * s.phase_sigma);
  return R;
}

// One configured filter: the EKF or the REKF on the 15-state model, with Q (196) and the
// REKF's uncertainty (197) refreshed at every step.
class FilterRunner {
 public:
  FilterRunner(const GpsInsScenario& s, const GpsInsFilterSettings& f, const State& x0, const Mat15& P0)
      : settings_(f), params_(s.model_parameters(f.jacobian)), scale_(f.scale_factor * P0.diagonal().cwiseSqrt()) {
    params_.propagation = f.propagation;
    noise_.accel_sigma = s.accel_sigma;
    noise_.torque_sigma = s.torque_sigma;
    noise_.bias_walk_sigma = s.gyro_bias_walk_sigma;
    noise_.inertia_uncertainty_fraction = f.inertia_uncertainty_fraction;
    noise_.zoh = f.zoh_process_noise;
    const Mat15 Q = models::gps_ins_process_noise(params_, noise_, Eigen::Vector3d::Zero());
    const ObsCov R = measurement_covariance(s);
    if (f.kind == GpsInsFilterKind::Ekf) {
      ekf_.emplace(GpsInsProcess(params_), GpsInsMeasurement(params_), Q, R);
      ekf_->init(x0, P0);
    } else {
      rekf_.emplace(GpsInsProcess(params_), GpsInsMeasurement(params_), Q, R, f.gamma, Mat15::Zero(), ObsCov::Zero(),
                    Mat15::Zero());
      rekf_->init(x0, P0);
      A_.setZero();
      C_.setZero();
      L_ = models::gps_ins_rekf_L(scale_);
    }
  }

  const State& x() const { return ekf_ ? ekf_->x() : rekf_->x(); }
  const Mat15& P() const { return ekf_ ? ekf_->P() : rekf_->P(); }

  // Q (196) with the inertia term at x̂(k−1) when p_f > 0; for the REKF, A_k (197) from F at
  // x̂(k−1).
  runtime::FilterStatus predict(const models::GpsInsEpoch& e, const Eigen::Vector3d& T_c) {
    if (settings_.inertia_uncertainty_fraction > 0) {
      const models::GpsInsRates r = models::gps_ins_rates(params_, e.R_FR, x().segment<3>(ix::kAttitude),
                                                          x().segment<3>(ix::kRate));
      const Mat15 Q = models::gps_ins_process_noise(params_, noise_, r.omega_BI);
      ekf_ ? ekf_->set_Q(Q) : rekf_->set_Q(Q);
    }
    if (ekf_) {
      ekf_->mutable_model().set_epoch(e);
      return ekf_->predict(T_c);
    }
    rekf_->mutable_model().set_epoch(e);
    A_ = models::gps_ins_rekf_A(rekf_->model().continuous_jacobian(x()), scale_, params_.sample_time,
                                settings_.kappa_A);
    rekf_->set_uncertainty(A_, C_, L_);
    return rekf_->predict(T_c);
  }

  // For the REKF, C_k (197) from H at x̂(k|k−1).
  runtime::FilterStatus update(const models::GpsInsEpoch& e, const GpsInsMeasurement::Vector& z) {
    if (ekf_) {
      ekf_->mutable_measurement().set_epoch(e);
      return ekf_->update(z);
    }
    rekf_->mutable_measurement().set_epoch(e);
    C_ = models::gps_ins_rekf_C(rekf_->measurement().H(x()), scale_, settings_.kappa_C);
    rekf_->set_uncertainty(A_, C_, L_);
    return rekf_->update(z);
  }

 private:
  GpsInsFilterSettings settings_;
  models::GpsInsParameters params_;
  models::GpsInsProcessNoise noise_;
  State scale_;
  Mat15 A_, L_;                                // the REKF's A_k and L of (197)
  models::GpsInsMeasurementUncertainty C_;     // and its C_k (square factor)
  std::optional<runtime::Ekf<GpsInsProcess, GpsInsMeasurement>> ekf_;
  std::optional<runtime::Rekf<GpsInsProcess, GpsInsMeasurement>> rekf_;
};

// Running maximum and sum of squares of the window's errors, per component.
struct WindowAccumulator {
  Eigen::Matrix<double, 15, 1> max_abs = Eigen::Matrix<double, 15, 1>::Zero();
  Eigen::Matrix<double, 15, 1> sum_sq = Eigen::Matrix<double, 15, 1>::Zero();
  double nees_sum = 0;
  long count = 0;

  // e in report units: m, m/s, deg (3-1-2), deg/s, deg/s
  void add(const Eigen::Matrix<double, 15, 1>& e, double nees) {
    max_abs = max_abs.cwiseMax(e.cwiseAbs());
    sum_sq += e.cwiseProduct(e);
    nees_sum += nees;
    ++count;
  }
  void write(GpsInsFilterStatistics& s) const {
    const Eigen::Matrix<double, 15, 1> rms = (sum_sq / std::max<long>(count, 1)).cwiseSqrt();
    s.position_max = max_abs.segment<3>(0), s.velocity_max = max_abs.segment<3>(3);
    s.attitude_max = max_abs.segment<3>(6), s.rate_max = max_abs.segment<3>(9), s.bias_max = max_abs.segment<3>(12);
    s.position_rms = rms.segment<3>(0), s.velocity_rms = rms.segment<3>(3), s.attitude_rms = rms.segment<3>(6);
    s.rate_rms = rms.segment<3>(9), s.bias_rms = rms.segment<3>(12);
    s.nees_mean = count ? nees_sum / count : 0.0;
  }
};

GpsInsSample sample_of(double t, const State& truth, const State& estimate, const Mat15& P) {
  GpsInsSample out;
  out.t = t;
  out.truth = truth;
  out.estimate = estimate;
  out.error = models::gps_ins_boxminus(truth, estimate);
  out.sigma = P.diagonal().cwiseMax(0.0).cwiseSqrt();
  const Eigen::Matrix3d R_err = models::mrp_to_dcm(truth.segment<3>(ix::kAttitude)) *
                                models::mrp_to_dcm(estimate.segment<3>(ix::kAttitude)).transpose();
  out.attitude_error_deg = models::euler312_from_dcm(R_err) / models::kRadiansPerDegree;
  const Eigen::LDLT<Mat15> ldlt(P);
  out.nees = out.error.dot(ldlt.solve(out.error));
  return out;
}

}  // namespace

Eigen::Matrix<double, 15, 1> error_in_report_units(const GpsInsSample& s) {
  Eigen::Matrix<double, 15, 1> e = s.error;
  e.segment<3>(ix::kAttitude) = s.attitude_error_deg;
  e.tail<6>() /= models::kRadiansPerDegree;
  return e;
}

Eigen::Matrix<double, 15, 1> sigma_in_report_units(const GpsInsSample& s) {
  Eigen::Matrix<double, 15, 1> v = s.sigma;
  v.segment<3>(ix::kAttitude) *= 4 / models::kRadiansPerDegree;
  v.tail<6>() /= models::kRadiansPerDegree;
  return v;
}

std::vector<GpsInsFilterStatistics> run_gps_ins(const GpsInsScenario& scenario,
                                                const std::vector<GpsInsFilterSettings>& filters,
                                                const GpsInsRunOptions& options, std::uint64_t seed) {
  const GpsInsTruth truth(scenario);
  Rng process_rng(derive_seed(seed, 1)), sensor_rng(derive_seed(seed, 2)), initial_rng(derive_seed(seed, 3));
  GpsInsTruthState y = truth.initial_state();

  // x̂(0) = x(0) ⊞ δ, δ ~ N(0, P0) (bias: b̂(0) = 0)
  const State sigma0 = initial_sigma(options.initial_error);
  const Mat15 P0 = sigma0.cwiseProduct(sigma0).asDiagonal();
  models::GpsInsEpoch e0 = truth.epoch(0);
  State x_true = truth.relative_state(y, e0);  // the truth at t (the loop's start)
  State delta = State::Zero();
  if (options.initial_error.sample)
    for (int i = 0; i < ix::kBias; ++i) delta(i) = sigma0(i) * initial_rng.normal();
  State x0 = models::gps_ins_boxplus(x_true, delta);
  x0.segment<3>(ix::kBias).setZero();

  std::vector<FilterRunner> runners;
  runners.reserve(filters.size());
  for (const auto& f : filters) runners.emplace_back(scenario, f, x0, P0);
  std::vector<WindowAccumulator> windows(filters.size());
  std::vector<GpsInsFilterStatistics> stats(filters.size());

  const double dt = scenario.sample_time;
  const long steps = std::lround(scenario.duration / dt);
  for (long k = 0; k < steps; ++k) {
    const double t1 = (k + 1) * dt;
    const Eigen::Vector3d T_c = truth.control_torque(y, x_true);
    Eigen::Vector3d T_d, accel;
    for (int i = 0; i < 3; ++i) T_d(i) = scenario.torque_sigma * process_rng.normal();
    for (int i = 0; i < 3; ++i) accel(i) = scenario.accel_sigma * process_rng.normal();
    truth.step(y, T_c + T_d, accel, process_rng);
    const models::GpsInsEpoch e1 = truth.epoch(t1);
    x_true = truth.relative_state(y, e1);
    const auto z = truth.measure(x_true, e1, sensor_rng);
    for (std::size_t i = 0; i < runners.size(); ++i) {
      GpsInsFilterStatistics& s = stats[i];
      for (const runtime::FilterStatus status : {runners[i].predict(e0, T_c), runners[i].update(e1, z)}) {
        if (status == runtime::FilterStatus::GammaConditionViolated) ++s.gamma_violations;
        else if (status != runtime::FilterStatus::Ok) ++s.failed_steps;
      }
      const GpsInsSample sample = sample_of(t1, x_true, runners[i].x(), runners[i].P());
      if (options.on_sample) options.on_sample(static_cast<int>(i), sample);
      if (!sample.error.allFinite() ||
          (t1 >= kDivergenceCheckStart && sample.error.head<3>().norm() > kDivergedPositionError))
        s.diverged = true;
      if (t1 >= options.window_start && t1 <= options.window_end) windows[i].add(error_in_report_units(sample), sample.nees);
    }
    e0 = e1;
  }
  for (std::size_t i = 0; i < runners.size(); ++i) windows[i].write(stats[i]);
  return stats;
}

}  // namespace hinf::sim
