// The truth of a gps_ins_relative run (docs/maths.md §30): the chaser's position and
// velocity relative to the target in LVLH (two-body difference, or CW), its inertial
// attitude q_BI and rate ω_BI under Euler's equation with the TRUE inertia, the gyro bias
// (a random walk); the target on its circular orbit; the frames and satellites of each
// epoch; the sensors. RK4 with the control torque, the disturbance torque and the
// acceleration perturbation held over each sample.
#pragma once
#include <Eigen/Dense>

#include "hinf/models/gps_ins.hpp"
#include "hinf/sim/gps_ins_scenario.hpp"
#include "hinf/sim/rng.hpp"

namespace hinf::sim {

struct GpsInsTruthState {
  Eigen::Matrix<double, 6, 1> translation;  // ρ, ρ̇ in LVLH
  Eigen::Quaterniond q_IB;                  // active rotation B → I (R_BI = its matrix transposed)
  Eigen::Vector3d omega_BI;                 // rad/s, in B
  Eigen::Vector3d bias;                     // gyro bias, rad/s
};

class GpsInsTruth {
 public:
  explicit GpsInsTruth(const GpsInsScenario& s);

  GpsInsTruthState initial_state() const;
  models::GpsInsEpoch epoch(double t) const;
  // The filter's state vector of the truth at the epoch e: [ρ; ρ̇; σ (B relative to F); ω; b].
  models::GpsInsProcess::State relative_state(const GpsInsTruthState& y, const models::GpsInsEpoch& e) const;
  models::GpsInsProcess::State relative_state(const GpsInsTruthState& y, double t) const {
    return relative_state(y, epoch(t));
  }
  // The PD law with gyroscopic feed-forward on the true relative state x, J_nom (§30.2).
  Eigen::Vector3d control_torque(const GpsInsTruthState& y, const models::GpsInsProcess::State& x) const;
  Eigen::Vector3d control_torque(const GpsInsTruthState& y, double t) const {
    return control_torque(y, relative_state(y, t));
  }
  // One sample: RK4 over Δt with T_c + T_d (N m) and the acceleration a (m/s²) held, then the
  // bias random walk b ← b + σ_b √Δt ξ.
  void step(GpsInsTruthState& y, const Eigen::Vector3d& torque, const Eigen::Vector3d& accel, Rng& rng) const;
  // z of docs/maths.md (193) of the true relative state x at the epoch e, with the sensors' noise.
  models::GpsInsMeasurement::Vector measure(const models::GpsInsProcess::State& x, const models::GpsInsEpoch& e,
                                            Rng& rng) const;
  models::GpsInsMeasurement::Vector measure(const GpsInsTruthState& y, double t, Rng& rng) const {
    const models::GpsInsEpoch e = epoch(t);
    return measure(relative_state(y, e), e, rng);
  }
  // The derivative of ω_BI (Euler's equation, J_true).
  Eigen::Vector3d omega_BI_dot(const Eigen::Vector3d& w, const Eigen::Vector3d& torque) const;

  const models::GpsInsParameters& parameters() const { return params_; }

 private:
  struct Derivative {
    Eigen::Matrix<double, 6, 1> translation;
    Eigen::Vector4d q;
    Eigen::Vector3d omega;
  };
  Derivative derivative(const Eigen::Matrix<double, 6, 1>& tr, const Eigen::Quaterniond& q, const Eigen::Vector3d& w,
                        const Eigen::Vector3d& torque, const Eigen::Vector3d& accel) const;

  GpsInsScenario s_;
  models::GpsInsParameters params_;
  models::GpsInsMeasurement sensors_;  // h of (193); its epoch is set on a copy per sample
  models::RelativeTwoBody two_body_;
  Eigen::Matrix3d J_true_, J_true_inv_, J_nom_, R_FR0_, R_RI0_;
  Eigen::Matrix<double, 6, 6> cw_;
  std::array<Eigen::Vector3d, models::kGpsInsSatellites> satellite_offsets_;
};

}  // namespace hinf::sim
