// One run of the gps_ins_relative family (docs/maths.md §29–§30): the truth, one measurement
// stream, every configured filter (EKF or REKF on the 15-state model) on that stream, and
// the per-filter statistics over the steady-state window (the source's statistic: the
// maximum absolute error of each component; and the RMS).
#pragma once
#include <Eigen/Dense>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hinf/models/gps_ins.hpp"
#include "hinf/sim/gps_ins_scenario.hpp"

namespace hinf::sim {

enum class GpsInsFilterKind { Ekf, Rekf };

struct GpsInsFilterSettings {
  std::string name = "ekf";
  GpsInsFilterKind kind = GpsInsFilterKind::Ekf;
  models::GpsInsJacobian jacobian = models::GpsInsJacobian::Full;
  models::GpsInsPropagation propagation = models::GpsInsPropagation::Exact;
  double inertia_uncertainty_fraction = 0;  // p_f of (196)
  bool zoh_process_noise = false;
  // REKF (197)
  double gamma = 1.0;
  double scale_factor = 2.0;  // s = scale_factor × σ0
  double kappa_A = 0.1;
  double kappa_C = 1e-3;
  // Explicit constant REKF uncertainty, replacing (197)'s per step: A and L 15 × 15, C NZ × 15
  // (NZ = 19 rows of single differences, 16 of double differences; passed as [C 0]).
  std::optional<Eigen::Matrix<double, 15, 15>> A, L;
  std::optional<Eigen::MatrixXd> C;
};

// The initial estimate's 1σ (and P0 = their squares); b̂(0) = 0.
struct GpsInsInitialError {
  double position = 10;                                     // m
  double velocity = 0.01;                                   // m/s
  double attitude = 1 * models::kRadiansPerDegree;          // rad (per axis)
  double rate = 0.01 * models::kRadiansPerDegree;           // rad/s
  double bias = 5.0 / 3600 * models::kRadiansPerDegree;     // rad/s
  bool sample = true;  // draw x̂(0) − x(0) from N(0, P0); else start at the truth (bias 0)
};

// Window statistics of one filter in one run. Errors: position, velocity in LVLH (m, m/s);
// attitude as 3-1-2 angles of R_true R_estᵀ (deg); rate and bias (deg/s).
struct GpsInsFilterStatistics {
  Eigen::Vector3d position_max, velocity_max, attitude_max, rate_max, bias_max;
  Eigen::Vector3d position_rms, velocity_rms, attitude_rms, rate_rms, bias_rms;
  double nees_mean = 0;
  long gamma_violations = 0;
  long failed_steps = 0;  // any other status than Ok
  bool diverged = false;  // NaN, or position error > 10 m after 2000 s
};

// One sample of one filter, for trajectory.csv.
struct GpsInsSample {
  double t;
  models::GpsInsProcess::State truth, estimate;
  Eigen::Matrix<double, 15, 1> error;  // truth ⊟ estimate (error coordinates)
  Eigen::Matrix<double, 15, 1> sigma;  // √diag P
  Eigen::Vector3d attitude_error_deg;  // 3-1-2 angles
  double nees;
};

// The sample's error and its 1σ in report units: m, m/s, deg (the 3-1-2 angles; σ as 4 × the
// MRP σ), deg/s — the units of the window statistics and of trajectory.csv.
Eigen::Matrix<double, 15, 1> error_in_report_units(const GpsInsSample& s);
Eigen::Matrix<double, 15, 1> sigma_in_report_units(const GpsInsSample& s);

struct GpsInsRunOptions {
  double window_start = 4000, window_end = 10000;  // s
  GpsInsInitialError initial_error;
  // Called for every filter and sample when set (filter index, sample).
  std::function<void(int, const GpsInsSample&)> on_sample;
};

std::vector<GpsInsFilterStatistics> run_gps_ins(const GpsInsScenario& scenario,
                                                const std::vector<GpsInsFilterSettings>& filters,
                                                const GpsInsRunOptions& options, std::uint64_t seed);

}  // namespace hinf::sim
