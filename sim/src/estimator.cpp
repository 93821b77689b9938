#include "hinf/sim/estimator.hpp"

#include <hinf/runtime/ekf.hpp>
#include <hinf/runtime/lti_filter.hpp>
#include <hinf/models/cartesian_position.hpp>
#include <hinf/models/hill.hpp>
#include <hinf/models/range_azimuth_elevation.hpp>
#include <hinf/runtime/rekf.hpp>

namespace hinf::sim {
namespace {

namespace rt = hinf::runtime;

class LtiEstimator final : public Estimator {
 public:
  LtiEstimator(const LtiGains& g, const Vector6& z0)
      : filter_(g.A_F, g.B_F, g.C_F, Matrix::Zero(g.A_F.rows(), 0), g.D_F) {
    filter_.init(z0);
  }
  Vector6 estimate(const MeasurementSample& y, double /*t*/) override {
    return filter_.step(y.cartesian);  // z_F(k) (+ D_F y(k)), then x_F(k+1) = A_F x_F(k) + B_F y(k)
  }
  void advance(const Vector3&, double) override {}

 private:
  rt::LtiFilter filter_;
};

using HillEkf = rt::Ekf<hinf::models::HillModel, hinf::models::CartesianPosition>;

Eigen::Matrix<double, 6, 6> process_covariance(double sample_time, double acceleration_variance) {
  Eigen::Matrix<double, 6, 3> G;
  G << 0.5 * sample_time * sample_time * Eigen::Matrix3d::Identity(), sample_time * Eigen::Matrix3d::Identity();
  return acceleration_variance * G * G.transpose();
}

// The measurement noise covariance of the Kalman filters (EKF and REKF): the first-order
// covariance of the Cartesian conversion at the sample (docs/maths.md (82)) plus the floor.
Eigen::Matrix3d measurement_covariance(const KalmanSettings& k, const MeasurementSample& y) {
  return hinf::models::RangeAzimuthElevation::covariance_through(y.jacobian, std::sqrt(k.range_variance),
                                                                 std::sqrt(k.azimuth_variance),
                                                                 std::sqrt(k.elevation_variance)) +
         k.r_floor * Eigen::Matrix3d::Identity();
}

class EkfEstimator final : public Estimator {
 public:
  EkfEstimator(const Scenario& s, const KalmanSettings& k)
      : settings_(k),
        ekf_(hinf::models::HillModel(s.orbital_rate, s.chaser_mass, s.sample_time, hinf::models::Discretisation::ZeroOrderHold),
             hinf::models::CartesianPosition(), process_covariance(s.sample_time, k.acceleration_variance),
             Eigen::Matrix3d::Identity()) {
    ekf_.init(s.initial_estimate, Eigen::Matrix<double, 6, 1>(s.initial_sigma.cwiseAbs2()).asDiagonal());
  }
  Vector6 estimate(const MeasurementSample& y, double t) override {
    ekf_.set_R(measurement_covariance(settings_, y));
    const rt::FilterStatus status = ekf_.update(y.cartesian);
    record(status == rt::FilterStatus::Ok, rt::to_string(status), t);
    return ekf_.x();
  }
  void advance(const Vector3& thrust, double t) override {
    const Vector3 u = settings_.knows_thrust ? thrust : Vector3::Zero();
    const rt::FilterStatus status = ekf_.predict(u);
    record(status == rt::FilterStatus::Ok, rt::to_string(status), t);
  }

 private:
  KalmanSettings settings_;
  HillEkf ekf_;
};

}  // namespace

std::unique_ptr<Estimator> make_lti_estimator(const LtiGains& gains, const Vector6& z0) {
  return std::make_unique<LtiEstimator>(gains, z0);
}

KalmanSettings kalman_settings_from(const Scenario& s, bool knows_thrust) {
  KalmanSettings k;
  k.acceleration_variance = channel_variance(s.process_noise);
  k.range_variance = channel_variance(s.range_noise);
  k.azimuth_variance = channel_variance(s.azimuth_noise);
  k.elevation_variance = channel_variance(s.elevation_noise);
  k.knows_thrust = knows_thrust;
  return k;
}

std::unique_ptr<Estimator> make_ekf_estimator(const Scenario& scenario, const KalmanSettings& settings) {
  return std::make_unique<EkfEstimator>(scenario, settings);
}

}  // namespace hinf::sim

// ---- REKF (docs/maths.md §13) ------------------------------------------------------

namespace hinf::sim {
namespace {

using HillRekf = hinf::runtime::Rekf<hinf::models::HillModel, hinf::models::CartesianPosition>;

class RekfEstimator final : public Estimator {
 public:
  RekfEstimator(const Scenario& s, const KalmanSettings& k, const RekfSettings& r)
      : settings_(k), rekf_(make(s, k, r)) {
    rekf_.init(s.initial_estimate, Eigen::Matrix<double, 6, 1>(s.initial_sigma.cwiseAbs2()).asDiagonal());
  }
  Vector6 estimate(const MeasurementSample& y, double t) override {
    rekf_.set_R(measurement_covariance(settings_, y));
    const auto status = rekf_.update(y.cartesian);
    record(status == hinf::runtime::FilterStatus::Ok, hinf::runtime::to_string(status), t);
    return rekf_.x();
  }
  void advance(const Vector3& thrust, double t) override {
    const auto status = rekf_.predict(thrust);
    record(status == hinf::runtime::FilterStatus::Ok, hinf::runtime::to_string(status), t);
  }

 private:
  static HillRekf make(const Scenario& s, const KalmanSettings& k, const RekfSettings& r) {
    const hinf::models::HillModel model(s.orbital_rate, s.chaser_mass, s.sample_time,
                                        hinf::models::Discretisation::ZeroOrderHold);
    // The filter model's own uncertainty, ΔA = H F(δ) E with F Fᵀ ≤ I (docs/maths.md (67)–(74)):
    // A_k = H = Γ·H_a of the ZOH model, L = E_a(δ̄), C_k = 0.
    const Eigen::Matrix<double, 6, 6> A_k =
        r.delta_bar > 0 ? model.uncertainty_H() : Eigen::Matrix<double, 6, 6>::Zero();
    const Eigen::Matrix<double, 6, 6> L =
        r.delta_bar > 0 ? model.uncertainty_E(r.delta_bar) : Eigen::Matrix<double, 6, 6>::Zero();
    double gamma = r.gamma ? *r.gamma : 1.0;
    if (!r.gamma && r.delta_bar > 0) {
      const Eigen::Matrix<double, 6, 6> P0 = Eigen::Matrix<double, 6, 1>(s.initial_sigma.cwiseAbs2()).asDiagonal();
      const Eigen::Matrix<double, 6, 6> LPL = L * P0 * L.transpose();
      gamma = std::sqrt(2.0 * Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>(LPL).eigenvalues().maxCoeff());
    }
    return HillRekf(model, hinf::models::CartesianPosition(), process_covariance(s.sample_time, k.acceleration_variance),
                    Eigen::Matrix3d::Identity(), gamma, A_k, Eigen::Matrix3d::Zero(), L);
  }
  KalmanSettings settings_;
  HillRekf rekf_;
};

}  // namespace

std::unique_ptr<Estimator> make_rekf_estimator(const Scenario& scenario, const KalmanSettings& settings,
                                               const RekfSettings& rekf) {
  return std::make_unique<RekfEstimator>(scenario, settings, rekf);
}

}  // namespace hinf::sim
