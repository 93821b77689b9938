// One run of the gyroless_attitude family (docs/maths.md §31): the RK4 truth with the
// harmonic torques, one star-tracker stream, every configured augmented EKF on that stream,
// and each filter's statistics over the steady-state window.
#pragma once
#include <Eigen/Dense>

#include <cstdint>
#include <functional>
#include <vector>

#include "hinf/models/rigid_body.hpp"
#include "hinf/sim/gyroless_scenario.hpp"

namespace hinf::sim {

// Window statistics of one filter in one run. Attitude errors 2δq_v of (212) in deg (roll,
// pitch, yaw about the body axes), torque errors in N m.
struct GyrolessFilterStatistics {
  Eigen::Vector3d attitude_rms_deg = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_rms = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_rate_correlation = Eigen::Vector3d::Zero();  // per axis, corr(|e_T,i|, |Ṫ_d,i|)
  double attitude_rms_norm_deg = 0;  // norm over the axes of the per-axis RMS
  double torque_rms_norm = 0;
  double torque_p95 = 0;              // nearest-rank 95th percentile of |e_T| over the window
  double attitude_max_deg = 0;        // max of |2δq_v| over the window
  double torque_rate_correlation_norm = 0;  // corr(|e_T|, |Ṫ_d|)
  double nees_mean = 0;               // 9 degrees of freedom
  long lambda_cap_hits = 0;           // ASTEKF steps with a λ_i at λ_max (whole run)
  long steps = 0;                     // filter steps in the run
  long failed_steps = 0;              // statuses other than Ok and FadingFactorCapped
  bool stopped = false;               // the filter stopped on a non-finite state
};

// One sample of one filter, for trajectory.csv and the plots.
struct GyrolessSample {
  double t;
  models::RigidBodyAttitudeProcess::State truth, estimate;
  Eigen::Vector3d torque_rate;                   // Ṫ_d(t), N m/s
  Eigen::Matrix<double, 9, 1> error;             // truth ⊟ estimate, (212)
  Eigen::Matrix<double, 9, 1> sigma;             // √diag P
  Eigen::Vector3d q_torque;                      // diag of the Q_T the filter used in this step
  Eigen::Matrix<double, 9, 1> lambda;            // the fading factors (1 without fading)
  double nees;
};

struct GyrolessRunOptions {
  double window_start = 600;  // s
  GyrolessInitialEstimate estimate;
  // Called for every filter and sample when set (filter index, sample).
  std::function<void(int, const GyrolessSample&)> on_sample;
};

std::vector<GyrolessFilterStatistics> run_gyroless(const GyrolessScenario& scenario,
                                                   const std::vector<GyrolessFilterSettings>& filters,
                                                   const GyrolessRunOptions& options, std::uint64_t seed);

// The truth's state at every sample t_k = k Δt, k = 0 … N (q, ω, T_d(t_k)), by RK4 with
// `truth_substeps` steps per sample and the torque evaluated inside the steps.
std::vector<models::RigidBodyAttitudeProcess::State> gyroless_truth(const GyrolessScenario& scenario);

}  // namespace hinf::sim
