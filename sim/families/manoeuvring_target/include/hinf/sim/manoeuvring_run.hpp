// One run of the manoeuvring_target family (docs/maths.md §32): the truth, one measurement
// stream (range/azimuth/elevation in LVLH1, the chaser's INS state and command), every
// configured transient-model manoeuvre estimator on that stream, and each one's metrics per
// window (docs/experiments.md "Seed 001").
#pragma once
#include <Eigen/Dense>

#include <cstdint>
#include <functional>
#include <vector>

#include "hinf/sim/manoeuvring_scenario.hpp"
#include "hinf/sim/manoeuvring_truth.hpp"

namespace hinf::sim {

// One step k of one filter: the state at t = t_{k+1}, the manoeuvre estimate over
// [t_k, t_{k+1}] (time tag u_time = t_k) against the truth averaged over that interval.
struct ManoeuvringSample {
  double t = 0, u_time = 0;
  Eigen::Matrix<double, 6, 1> truth, estimate, sigma;  // LVLH0; sigma = √diag P(t|t)
  Eigen::Vector3d measured_position;                   // Y = T_m h(Z), LVLH0
  Eigen::Vector3d true_u, u_hat, u_var_paper, u_var_innovation, u_chaser;  // m/s², (m/s²)²
  double nis = 0, window_nis = 0, range = 0;
  bool tested = false, alarm = false, updated = false;  // tested: the detector's window was full
};

// The metrics of one filter over one window (per-axis LVLH0 x, y, z).
struct ManoeuvringWindowStatistics {
  Eigen::Vector3d position_rms, velocity_rms, position_error_max;  // m, m/s, m
  Eigen::Vector3d u_error_mean, u_error_rms, u_error_max;          // m/s²
  Eigen::Vector3d u_sigma_paper, u_sigma_innovation;               // √(mean variance), m/s²
  Eigen::Vector3d coverage_paper, coverage_innovation;             // fraction with |e| ≤ 3σ
  long samples = 0;
};

struct ManoeuvringFilterStatistics {
  std::vector<ManoeuvringWindowStatistics> windows;  // in the order of the options' windows
  // Seconds from the first target manoeuvre's onset (offset) until |Û − U| ≤ tolerance holds
  // per axis up to its offset (the end); NaN if never, or if no target manoeuvre.
  Eigen::Vector3d settle_after_onset, settle_after_offset;
  double detection_delay = 0;     // s from onset to the first alarm; NaN if none or no detector
  double false_alarm_rate = 0;    // alarms per full-window test before the onset; NaN if no test
  double final_position_error = 0;  // |X_pos error| at the last sample, m
  long failed_steps = 0;
};

struct ManoeuvringRunOptions {
  ManoeuvringEstimate estimate;
  std::vector<MetricWindow> windows{{"pre", 50, 300}, {"manoeuvre", 360, 600}, {"post", 660, 1000}};
  double maneuver_tolerance = 0.05;  // m/s², for the settle times
  // Called for every filter and step when set (filter index, sample).
  std::function<void(int, const ManoeuvringSample&)> on_sample;
};

std::vector<ManoeuvringFilterStatistics> run_manoeuvring(const ManoeuvringScenario& scenario,
                                                         const std::vector<ManoeuvreFilterSettings>& filters,
                                                         const ManoeuvringRunOptions& options, std::uint64_t seed);

// The detector's threshold: the (1 − P_FA) quantile of χ² with 3w degrees of freedom, (226).
double nis_window_threshold(int window, double p_false_alarm);

}  // namespace hinf::sim
