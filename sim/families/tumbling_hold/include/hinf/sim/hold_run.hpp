// One tumbling_hold run (docs/experiments.md "Seed 004"): the truth of hold_truth.hpp at
// the integration step, the camera and the discrete controller at the control period
// (u = U* + C_K x_K + D_K e, e = y − ρ*), the modulator and the thrusters at the integration
// step; and its metrics.
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <optional>
#include <vector>

#include "hinf/models/controller.hpp"
#include "hinf/sim/hold_scenario.hpp"
#include "hinf/sim/plots.hpp"

namespace hinf::sim {

// Everything the runs share, prepared once.
struct HoldSetup {
  HoldScenario scenario;
  hinf::Controller controller;  // discrete, period scenario.control_sample_time; input e (3), output U_fb (3)
  Eigen::Vector3d feedforward = Eigen::Vector3d::Zero();  // U*, N (zero without feedforward)
};

struct HoldMetrics {
  // over the steady-state window t ≥ steady_state_start, at the control samples:
  double position_rms_m = 0;    // the largest per-axis RMS of ρ − ρ*
  double position_max_m = 0;    // the largest |ρ_i − ρ*_i|
  double velocity_rms_mps = 0;  // the largest per-axis RMS of ρ̇
  // first t after which |ρ − ρ*| < settle_threshold at every later sample; empty if the
  // last sample is not below it
  std::optional<double> settle_time_s;
  double delta_v_mps = 0;  // Σ over axes of ∫|F_i| dt / m (propellant)
  long pulse_count = 0;    // thruster pulses, all axes (a sign change ends one and starts another)
  std::optional<double> min_pulse_s;  // the shortest pulse that ended before the run did
  double saturation_fraction = 0;     // control samples with some |U_i| > F
};

struct HoldTrajectory {
  std::vector<double> t;                         // control samples t_k
  std::vector<Eigen::Vector3d> error, velocity;  // ρ − ρ*, ρ̇ at t_k
  std::vector<Eigen::Vector3d> command;          // U(t_k), N (NaN on the last sample)
  std::vector<Eigen::Vector3d> force;            // mean applied force over [t_k, t_k+1), N
  std::vector<Eigen::Vector3i> pulse;            // thruster state at t_k: −1, 0, +1
};

struct HoldRunResult {
  std::uint64_t seed = 0;
  HoldMetrics metrics;
  std::optional<HoldTrajectory> trajectory;
  RunTraces traces;  // |ρ − ρ*| and |ρ̇| (one "filter": the closed loop) for the Monte-Carlo figure
};

// The moving RMS's window of the Monte-Carlo figure (plots.hpp): 1 % of the duration.
double hold_trace_window(const HoldScenario& s);
// The figure's norms at every control sample: {|ρ − ρ*|, |ρ̇|}.
std::vector<std::vector<double>> hold_error_norms(const HoldTrajectory& tr);

// Throws SimulationError (run.hpp) on a non-finite truth.
HoldRunResult simulate_hold_run(const HoldSetup& setup, std::uint64_t run_seed, bool keep_trajectory);

}  // namespace hinf::sim
