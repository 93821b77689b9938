// run_gps_ins (gps_ins_run.hpp): docs/maths.md §29–§30.
#include "hinf/sim/gps_ins_run.hpp"

#include <cmath>
#include <optional>

#include "hinf/common/number_text.hpp"
#include "hinf/runtime/ekf.hpp"
#include "hinf/runtime/rekf.hpp"
#include "hinf/sim/gps_ins_truth.hpp"
#include "hinf/sim/rng.hpp"
#include "hinf/sim/simulation_error.hpp"

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

// The relative truth x (docs/maths.md §29–30) at sample k finite, else SimulationError.
void require_finite(long k, double t, const State& x) {
  require_finite_truth("gps_ins", k, t, x,
                       {{"relative position (m)", ix::kPosition, 3},
                        {"relative velocity (m/s)", ix::kVelocity, 3},
                        {"relative attitude (MRP)", ix::kAttitude, 3},
                        {"relative rate (rad/s)", ix::kRate, 3},
                        {"gyro bias (rad/s)", ix::kBias, 3}});
}

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

// The filters' measurement from the simulated single differences z (19 rows): z itself, or
// D z of (193a) — with R as D R Dᵀ.
template <class Measurement>
struct FromSingleDifference {
  static const typename Measurement::Vector& z(const GpsInsMeasurement::Vector& z) { return z; }
  static const ObsCov& R(const ObsCov& R) { return R; }
};
template <>
struct FromSingleDifference<models::GpsInsDoubleDifferenceMeasurement> {
  using DD = models::GpsInsDoubleDifferenceMeasurement;
  static DD::Vector z(const GpsInsMeasurement::Vector& z) { return D() * z; }
  static Eigen::Matrix<double, DD::NZ, DD::NZ> R(const ObsCov& R) { return D() * R * D().transpose(); }
  static const DD::Map& D() {
    static const DD::Map map = DD::map();
    return map;
  }
};

// One configured filter: the EKF or the REKF on the 15-state model with the measurement
// model `Measurement` (single or double differences), with Q (196) and the REKF's
// uncertainty (197) refreshed at every step (each of A, C, L the settings give explicitly is
// held constant instead).
template <class Measurement>
class FilterRunner {
  static constexpr int NZm = Measurement::NZ;
  using ObsCovM = Eigen::Matrix<double, NZm, NZm>;
  using Convert = FromSingleDifference<Measurement>;

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
    const ObsCovM R = Convert::R(measurement_covariance(s));
    if (f.kind == GpsInsFilterKind::Ekf) {
      ekf_.emplace(GpsInsProcess(params_), Measurement(params_), Q, R);
      ekf_->init(x0, P0);
    } else {
      rekf_.emplace(GpsInsProcess(params_), Measurement(params_), Q, R, f.gamma, Mat15::Zero(), ObsCovM::Zero(),
                    Mat15::Zero());
      rekf_->init(x0, P0);
      A_ = f.A.value_or(Mat15::Zero());
      C_.setZero();
      if (f.C) C_.template leftCols<15>() = *f.C;  // [C 0]: a square factor of C Cᵀ
      L_ = f.L.value_or(models::gps_ins_rekf_L(scale_));
    }
  }

  const State& x() const { return ekf_ ? ekf_->x() : rekf_->x(); }
  const Mat15& P() const { return ekf_ ? ekf_->P() : rekf_->P(); }

  // Q (196) with the inertia term at x̂(k−1) when p_f > 0; for the REKF, A_k (197) from F at
  // x̂(k−1).
  runtime::FilterStatus predict(const models::GpsInsEpoch& e, const Eigen::Vector3d& T_c) {
    if (settings_.inertia_uncertainty_fraction > 0) {
      const models::GpsInsRates r = models::gps_ins_rates(params_, e.R_FR, x().template segment<3>(ix::kAttitude),
                                                          x().template segment<3>(ix::kRate));
      const Mat15 Q = models::gps_ins_process_noise(params_, noise_, r.omega_BI);
      ekf_ ? ekf_->set_Q(Q) : rekf_->set_Q(Q);
    }
    if (ekf_) {
      ekf_->mutable_model().set_epoch(e);
      return ekf_->predict(T_c);
    }
    rekf_->mutable_model().set_epoch(e);
    if (!settings_.A)
      A_ = models::gps_ins_rekf_A(rekf_->model().continuous_jacobian(x()), scale_, params_.sample_time,
                                  settings_.kappa_A);
    rekf_->set_uncertainty(A_, C_, L_);
    return rekf_->predict(T_c);
  }

  // For the REKF, C_k (197) from H at x̂(k|k−1). z: the simulated single differences.
  runtime::FilterStatus update(const models::GpsInsEpoch& e, const GpsInsMeasurement::Vector& z) {
    if (ekf_) {
      ekf_->mutable_measurement().set_epoch(e);
      return ekf_->update(Convert::z(z));
    }
    rekf_->mutable_measurement().set_epoch(e);
    if (!settings_.C) C_ = models::gps_ins_rekf_C<NZm>(rekf_->measurement().H(x()), scale_, settings_.kappa_C);
    rekf_->set_uncertainty(A_, C_, L_);
    return rekf_->update(Convert::z(z));
  }

 private:
  GpsInsFilterSettings settings_;
  models::GpsInsParameters params_;
  models::GpsInsProcessNoise noise_;
  State scale_;
  Mat15 A_, L_;                                // the REKF's A_k and L of (197)
  ObsCovM C_;                                   // and its C_k (square factor)
  std::optional<runtime::Ekf<GpsInsProcess, Measurement>> ekf_;
  std::optional<runtime::Rekf<GpsInsProcess, Measurement>> rekf_;
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

// The truth and measurement stream of one run, at its start.
struct Stream {
  const GpsInsTruth& truth;
  GpsInsTruthState y;
  models::GpsInsEpoch e0;
  State x_true;
  Rng& process_rng;
  Rng& sensor_rng;
};

// Every filter on the stream, to its end: the window statistics.
template <class Measurement>
std::vector<GpsInsFilterStatistics> run_filters(const GpsInsScenario& scenario,
                                                const std::vector<GpsInsFilterSettings>& filters,
                                                const GpsInsRunOptions& options, Stream st, const State& x0,
                                                const Mat15& P0) {
  std::vector<FilterRunner<Measurement>> runners;
  runners.reserve(filters.size());
  for (const auto& f : filters) {
    try {
      runners.emplace_back(scenario, f, x0, P0);
    } catch (const std::invalid_argument& refusal) {
      throw scenario_settings_error("filters." + f.name, refusal,
                                    "the scenario's noise sigmas, gyro, initial error and this filter's settings");
    }
  }
  std::vector<WindowAccumulator> windows(filters.size());
  std::vector<GpsInsFilterStatistics> stats(filters.size());

  const double dt = scenario.sample_time;
  const long steps = std::lround(scenario.duration / dt);
  for (long k = 0; k < steps; ++k) {
    const double t1 = (k + 1) * dt;
    const Eigen::Vector3d T_c = st.truth.control_torque(st.y, st.x_true);
    Eigen::Vector3d T_d, accel;
    for (int i = 0; i < 3; ++i) T_d(i) = scenario.torque_sigma * st.process_rng.normal();
    for (int i = 0; i < 3; ++i) accel(i) = scenario.accel_sigma * st.process_rng.normal();
    st.truth.step(st.y, T_c + T_d, accel, st.process_rng);
    const models::GpsInsEpoch e1 = st.truth.epoch(t1);
    st.x_true = st.truth.relative_state(st.y, e1);
    require_finite(k + 1, t1, st.x_true);
    const auto z = st.truth.measure(st.x_true, e1, st.sensor_rng);
    for (std::size_t i = 0; i < runners.size(); ++i) {
      GpsInsFilterStatistics& s = stats[i];
      try {  // Q and the REKF's uncertainty are rebuilt at x̂ each step
        for (const runtime::FilterStatus status : {runners[i].predict(st.e0, T_c), runners[i].update(e1, z)}) {
          if (status == runtime::FilterStatus::GammaConditionViolated) ++s.gamma_violations;
          else if (status != runtime::FilterStatus::Ok) ++s.failed_steps;
        }
      } catch (const std::invalid_argument& refusal) {
        throw scenario_settings_error("filters." + filters[i].name, refusal,
                                      "the scenario's gyro, noise sigmas and this filter's settings, at t = " +
                                          number_text(t1) + " s");
      }
      const GpsInsSample sample = sample_of(t1, st.x_true, runners[i].x(), runners[i].P());
      if (options.on_sample) options.on_sample(static_cast<int>(i), sample);
      if (!sample.error.allFinite() ||
          (t1 >= kDivergenceCheckStart && sample.error.head<3>().norm() > kDivergedPositionError))
        s.diverged = true;
      if (t1 >= options.window_start && t1 <= options.window_end) windows[i].add(error_in_report_units(sample), sample.nees);
    }
    st.e0 = e1;
  }
  for (std::size_t i = 0; i < runners.size(); ++i) windows[i].write(stats[i]);
  return stats;
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
  require_finite(0, 0.0, x_true);
  State delta = State::Zero();
  if (options.initial_error.sample)
    for (int i = 0; i < ix::kBias; ++i) delta(i) = sigma0(i) * initial_rng.normal();
  State x0 = models::gps_ins_boxplus(x_true, delta);
  x0.segment<3>(ix::kBias).setZero();

  Stream stream{truth, y, e0, x_true, process_rng, sensor_rng};
  if (scenario.phase_mode == GpsInsScenario::PhaseMode::DoubleDifference)
    return run_filters<models::GpsInsDoubleDifferenceMeasurement>(scenario, filters, options, stream, x0, P0);
  return run_filters<GpsInsMeasurement>(scenario, filters, options, stream, x0, P0);
}

}  // namespace hinf::sim
