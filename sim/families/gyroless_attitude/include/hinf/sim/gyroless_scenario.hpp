// The gyroless_attitude scenario family (docs/maths.md §31, docs/experiments.md "Seed 002"):
// a rigid spacecraft without gyros, harmonic disturbance torques, a star tracker measuring two
// reference directions, and augmented EKFs (AEKF, ASTEKF, AAEKF) estimating attitude, rate
// and torque side by side on one measurement stream. Every field in SI units; the defaults
// are configs/scenarios/gyroless-attitude.yaml.
#pragma once
#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "hinf/models/rigid_body.hpp"
#include "hinf/runtime/prior_covariance.hpp"

namespace hinf::sim {

struct GyrolessScenario {
  double duration = 5855;   // s (one orbit)
  double sample_time = 1;   // s
  int truth_substeps = 10;  // RK4 steps per sample for the truth
  double orbital_rate = 0.06148839356680 * models::kRadiansPerDegree;  // ω_e, rad/s (650 km)
  Eigen::Matrix3d inertia = Eigen::Vector3d(20, 18, 15).asDiagonal();   // kg m²
  Eigen::Vector3d wheel_momentum = Eigen::Vector3d::Zero();             // N m s
  // T_d,i(t) = sign_i · amplitude_i · sin(harmonic_i · ω_e · t)
  Eigen::Vector3d torque_amplitude = Eigen::Vector3d::Constant(1e-5);  // N m
  Eigen::Vector3d torque_harmonic{6, 4, 8};
  Eigen::Vector3d torque_sign{-1, 1, -1};
  models::Quaternion q0{0, 0, 0, 1};
  Eigen::Vector3d w0 = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 2> reference_vectors{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1)};
  double star_tracker_variance = 1e-10;  // rad², per component

  Eigen::Vector3d torque(double t) const {
    return torque_sign.cwiseProduct(torque_amplitude)
        .cwiseProduct((torque_harmonic * (orbital_rate * t)).array().sin().matrix());
  }
  Eigen::Vector3d torque_rate(double t) const {
    const Eigen::Vector3d w = torque_harmonic * orbital_rate;
    return torque_sign.cwiseProduct(torque_amplitude).cwiseProduct(w).cwiseProduct((w * t).array().cos().matrix());
  }
};

enum class GyrolessFilterKind { Aekf, Astekf, Aaekf };

// The ASTEKF's and the AAEKF's defaults: the tunings of an independent re-implementation
// (docs/experiments.md "Seed 002"; the source gives none): K_b = 2, α = (1, …, 1, 2, 2, 2),
// ρ = 0.95, λ_max = 1e3; Q_initial = 1e-14, s = 1, ε = 3, m = 30, law diag, no floor.
inline runtime::StrongTrackingSettings<9> gyroless_strong_tracking_defaults() {
  runtime::StrongTrackingSettings<9> s;
  s.weakening = 2;
  s.alpha << 1, 1, 1, 1, 1, 1, 2, 2, 2;
  return s;
}
inline runtime::AdaptiveQSettings gyroless_adaptive_defaults() {
  runtime::AdaptiveQSettings a;
  a.initial = 1e-14;
  return a;
}

struct GyrolessFilterSettings {
  std::string name = "aekf";
  GyrolessFilterKind kind = GyrolessFilterKind::Aekf;
  double Q = 1e-14;  // Q_T of the torque random walk, (N m)²/s (AEKF, ASTEKF)
  runtime::StrongTrackingSettings<9> strong_tracking = gyroless_strong_tracking_defaults();  // ASTEKF
  runtime::AdaptiveQSettings adaptive = gyroless_adaptive_defaults();  // AAEKF (offsets and Δt set by the run)
  std::string swept_from;  // the filter a sweep entry was made from (empty if none)
};

// The filter's initial estimate and P0 = diag(σ²); with `sample`, the initial error is drawn
// from N(0, P0) (attitude as a rotation, the rest additive), else the estimate is as given.
struct GyrolessInitialEstimate {
  models::Quaternion q0{0, 0, 0, 1};
  Eigen::Vector3d w0 = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque0 = Eigen::Vector3d::Zero();
  double sigma_attitude = 1e-2;  // rad
  double sigma_rate = 1e-4;      // rad/s
  double sigma_torque = 1e-5;    // N m
  int prediction_substeps = 1;   // RK4 steps per sample in the filters' prediction
  bool sample = false;
};

}  // namespace hinf::sim
