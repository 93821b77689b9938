// GpsInsTruth (gps_ins_truth.hpp): docs/maths.md §30.
#include "hinf/sim/gps_ins_truth.hpp"

#include <cmath>

namespace hinf::sim {

using models::GpsInsProcess;
using models::GpsInsMeasurement;
namespace ix = models::gps_ins_index;

GpsInsTruth::GpsInsTruth(const GpsInsScenario& s)
    : s_(s),
      params_(s.model_parameters(models::GpsInsJacobian::Full)),
      sensors_(params_),
      two_body_(s.mu, s.orbit_rate()),
      J_true_(s.inertia_true()),
      J_true_inv_(J_true_.inverse()),
      J_nom_(s.inertia_nominal_matrix()),
      R_FR0_(s.flyaround_frame()),
      R_RI0_(s.lvlh_from_inertial0()),
      cw_(GpsInsProcess(params_).translation_matrix()),
      satellite_offsets_(s.satellite_offsets()) {}

models::GpsInsEpoch GpsInsTruth::epoch(double t) const {
  models::GpsInsEpoch e;
  e.R_FR = models::rotation_3(s_.flyaround_rate() * t) * R_FR0_;
  e.R_RI = models::rotation_3(s_.orbit_rate() * t) * R_RI0_;
  const Eigen::Matrix3d R_IR = e.R_RI.transpose();
  e.r_target = R_IR * Eigen::Vector3d(s_.orbit_radius, 0, 0);
  for (int j = 0; j < models::kGpsInsSatellites; ++j) e.r_satellite[j] = e.r_target + R_IR * satellite_offsets_[j];
  return e;
}

GpsInsTruthState GpsInsTruth::initial_state() const {
  GpsInsTruthState y;
  y.translation << s_.initial_position, s_.initial_velocity_used();
  // R_BI = R_BF R_FR R_RI at t = 0, R_BF from the 3-1-2 angles
  const models::GpsInsEpoch e = epoch(0);
  const Eigen::Matrix3d R_BF = models::dcm_from_euler312(s_.initial_euler312);
  const Eigen::Matrix3d R_BI = R_BF * e.R_FR * e.R_RI;
  y.q_IB = Eigen::Quaterniond(Eigen::Matrix3d(R_BI.transpose()));
  const models::GpsInsRates r = models::gps_ins_rates(params_, e.R_FR, models::mrp_from_dcm(R_BF), s_.initial_rate);
  y.omega_BI = r.omega_BI;
  y.bias = s_.gyro_bias_initial;
  return y;
}

GpsInsProcess::State GpsInsTruth::relative_state(const GpsInsTruthState& y, const models::GpsInsEpoch& e) const {
  const Eigen::Matrix3d R_BI = y.q_IB.toRotationMatrix().transpose();
  const Eigen::Vector3d sigma = models::mrp_from_dcm(R_BI * e.R_RI.transpose() * e.R_FR.transpose());
  const models::GpsInsRates r = models::gps_ins_rates(params_, e.R_FR, sigma, Eigen::Vector3d::Zero());
  GpsInsProcess::State x;
  x.head<6>() = y.translation;
  x.segment<3>(ix::kAttitude) = sigma;
  x.segment<3>(ix::kRate) = y.omega_BI - r.Omega - r.nu;
  x.segment<3>(ix::kBias) = y.bias;
  return x;
}

Eigen::Vector3d GpsInsTruth::control_torque(const GpsInsTruthState& y, const GpsInsProcess::State& x) const {
  if (s_.control == AttitudeControlLaw::None) return Eigen::Vector3d::Zero();
  return y.omega_BI.cross(J_nom_ * y.omega_BI) - s_.kp * x.segment<3>(ix::kAttitude) - s_.kd * x.segment<3>(ix::kRate);
}

Eigen::Vector3d GpsInsTruth::omega_BI_dot(const Eigen::Vector3d& w, const Eigen::Vector3d& torque) const {
  return J_true_inv_ * (torque - w.cross(J_true_ * w));
}

GpsInsTruth::Derivative GpsInsTruth::derivative(const Eigen::Matrix<double, 6, 1>& tr, const Eigen::Quaterniond& q,
                                                const Eigen::Vector3d& w, const Eigen::Vector3d& torque,
                                                const Eigen::Vector3d& accel) const {
  Derivative d;
  if (s_.truth_dynamics == GpsInsTruthDynamics::Cw) {
    d.translation = cw_ * tr;
    d.translation.tail<3>() += accel;
  } else {
    d.translation = two_body_.derivative(tr, accel);
  }
  const Eigen::Quaterniond q_dot = q * Eigen::Quaterniond(0, w.x(), w.y(), w.z());  // q̇ = ½ q ⊗ (0, ω)
  d.q << 0.5 * q_dot.w(), 0.5 * q_dot.x(), 0.5 * q_dot.y(), 0.5 * q_dot.z();
  d.omega = omega_BI_dot(w, torque);
  return d;
}

void GpsInsTruth::step(GpsInsTruthState& y, const Eigen::Vector3d& torque, const Eigen::Vector3d& accel,
                       Rng& rng) const {
  const double h = s_.sample_time / s_.truth_substeps;
  auto quat = [](const Eigen::Vector4d& v) { return Eigen::Quaterniond(v(0), v(1), v(2), v(3)); };
  for (int i = 0; i < s_.truth_substeps; ++i) {
    const Eigen::Vector4d q0(y.q_IB.w(), y.q_IB.x(), y.q_IB.y(), y.q_IB.z());
    const Derivative k1 = derivative(y.translation, y.q_IB, y.omega_BI, torque, accel);
    const Derivative k2 = derivative(y.translation + h / 2 * k1.translation, quat(q0 + h / 2 * k1.q),
                                     y.omega_BI + h / 2 * k1.omega, torque, accel);
    const Derivative k3 = derivative(y.translation + h / 2 * k2.translation, quat(q0 + h / 2 * k2.q),
                                     y.omega_BI + h / 2 * k2.omega, torque, accel);
    const Derivative k4 = derivative(y.translation + h * k3.translation, quat(q0 + h * k3.q), y.omega_BI + h * k3.omega,
                                     torque, accel);
    y.translation += h / 6 * (k1.translation + 2 * k2.translation + 2 * k3.translation + k4.translation);
    y.q_IB = quat(q0 + h / 6 * (k1.q + 2 * k2.q + 2 * k3.q + k4.q)).normalized();
    y.omega_BI += h / 6 * (k1.omega + 2 * k2.omega + 2 * k3.omega + k4.omega);
  }
  const double walk = s_.gyro_bias_walk_sigma * std::sqrt(s_.sample_time);
  for (int i = 0; i < 3; ++i) y.bias(i) += walk * rng.normal();
}

GpsInsMeasurement::Vector GpsInsTruth::measure(const GpsInsProcess::State& x, const models::GpsInsEpoch& e,
                                               Rng& rng) const {
  GpsInsMeasurement model = sensors_;
  model.set_epoch(e);
  GpsInsMeasurement::Vector z = model.h(x);
  for (int i = 0; i < 3; ++i) z(i) += s_.gyro_noise_sigma * rng.normal();
  for (int j = 0; j < models::kGpsInsSatellites; ++j) z(GpsInsMeasurement::kPseudorangeRow + j) += s_.pseudorange_sigma * rng.normal();
  for (int i = GpsInsMeasurement::kPhaseRow; i < GpsInsMeasurement::NZ; ++i) z(i) += s_.phase_sigma * rng.normal();
  return z;
}

}  // namespace hinf::sim
