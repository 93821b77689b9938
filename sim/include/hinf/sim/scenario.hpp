// A navigation experiment, as plain data (read by scenario_yaml.hpp, run by run.hpp).
// Units: SI (m, s, rad, N, kg). Frame: docs/maths.md §9.1 (x radial, y along-track, z normal).
#pragma once
#include <Eigen/Dense>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hinf/sim/metrics.hpp"
#include "hinf/sim/noise.hpp"

namespace hinf::sim {

using Matrix = Eigen::MatrixXd;

enum class ControlLaw { None, StateFeedback };       // u = 0, or u = K x̂ (docs/maths.md (66))
enum class ControlInput { Truth, Estimate };         // x̂ = true state, or the `hinf` estimate

// Where an LTI filter's gains come from: a gains file, or a synthesis config solved now.
struct LtiGainsSource {
  std::string gains_path;       // hinf-gains/1 file (absolute, or resolved against the scenario's directory)
  std::string synthesize_path;  // synthesis config (idem); exactly one of the two is set
};

struct RekfSettings {
  std::optional<double> gamma;  // γ of docs/maths.md §13; default (100): γ² = 2 λ_max(L P0 Lᵀ)
                                // (twice the smallest γ that the existence condition allows at P0)
  double delta_bar = 0.05;  // uncertainty of the orbital rate the REKF is told about:
                            // A_k = T·H_a, L = E_a(δ̄) (docs/maths.md (100)), C_k = 0
};

struct FilterSelection {
  std::optional<LtiGainsSource> hinf;       // the H∞ filter under test
  std::optional<LtiGainsSource> published;  // the paper's published gains
  bool ekf = false;                         // EKF that knows the applied thrust
  bool ekf_no_control = false;              // EKF that ignores the thrust
  std::optional<RekfSettings> rekf;         // REKF, docs/maths.md §13 (knows the applied thrust)
};

// A run has at most this many samples: the trajectory of every filter is kept in
// memory (~1 KB a sample), so 1e7 samples is ~10 GB — the most a 24 GB machine runs.
constexpr double kMaxSimulationSteps = 1e7;

// Why (duration, sample_time) is not a run's timing, or "" if it is: the duration must
// be a whole number of sample times, at least one and at most kMaxSimulationSteps of them.
// The one rule of the Hill scenario file and of hinf-sim's --duration in every family.
std::string timing_problem(double duration, double sample_time);

// --duration D of a run sampled every `sample_time` s: D, or Error(InvalidInput)
// "--duration D: <timing_problem>".
double checked_duration(double duration, double sample_time);

struct Scenario {
  std::string path;  // the file it was read from (for messages and relative paths)
  // orbit and chaser
  double mu = 3.986004418e14;        // m³/s²
  double orbital_rate = 7.2722e-5;   // ω₀, rad/s: the filters' nominal target orbit
  double chaser_mass = 1000.0;       // kg
  // timing
  double sample_time = 0.1;          // T, s (filters' and measurements' rate)
  double duration = 3000.0;          // s; steps = round(duration/T) + 1 rows (t = 0 … duration)
  int integrator_substeps = 10;      // RK4 substeps per sample
  // truth
  double truth_delta = 0.0;          // ω_true = ω₀(1+δ) (target radius from ω_true)
  Eigen::Matrix<double, 6, 1> initial_state;  // x(0)
  // control (K of docs/maths.md (66), (77))
  ControlLaw control_law = ControlLaw::None;
  ControlInput control_input = ControlInput::Truth;
  Matrix K;                          // 3×6
  // noise
  std::vector<NoiseComponent> process_noise;  // acceleration, m/s², per axis, held over T
  std::vector<NoiseComponent> range_noise;    // m
  std::vector<NoiseComponent> azimuth_noise;  // rad
  std::vector<NoiseComponent> elevation_noise;// rad
  Matrix C_bl = Matrix::Identity(3, 3);       // frame-to-body rotation (docs/maths.md (81))
  // estimation
  Eigen::Matrix<double, 6, 1> initial_estimate;  // docs/maths.md §9.8 (630, 520, 1000, 0, 0, 0)
  Eigen::Matrix<double, 6, 1> initial_sigma;     // EKF/REKF P0 = diag(σ²)
  double divergence_limit_m = 1e6;  // a position error beyond this counts as diverged
  FilterSelection filters;
  // metrics
  std::optional<double> steady_state_start;  // s; default duration/2
  double converge_threshold_m = 1.0;
  double converge_window_s = 0.0;  // s; 0 = pointwise error (MetricSettings)
  bool plots = true;

  long steps() const;                 // number of samples
  MetricSettings metric_settings() const;
};

}  // namespace hinf::sim
