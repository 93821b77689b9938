// A position-hold experiment near a spinning or tumbling target (scenario family
// `tumbling_hold`, docs/experiments.md "Seed 004"), as plain data: read by
// hold_scenario_yaml.hpp, run by hold_run.hpp. Units SI (m, s, rad, N, kg); every vector is
// in the target's body frame t (docs/maths.md §27).
#pragma once
#include <Eigen/Dense>
#include <string>

#include "hinf/runtime/pulse_modulator.hpp"

namespace hinf::sim {

enum class ModulatorKind { Ideal, Pwm, Pwpf };
const char* to_string(ModulatorKind k);

// Where the controller comes from: a controller file (hinf-controller/1) or a controller
// config synthesised now; exactly one is set (absolute, or resolved against the scenario).
struct ControllerSource {
  std::string file_path;
  std::string synthesize_path;
};

struct HoldScenario {
  std::string path;
  // timing
  double duration = 1500.0;          // s
  double integration_step = 1e-3;    // s: the truth's RK4 step and the thrusters' resolution
  double control_sample_time = 0.1;  // s: camera and controller period
  // target: torque-free rigid body on a circular orbit
  Eigen::Vector3d inertia{1200, 1000, 800};                  // J_t, kg m² (principal axes)
  Eigen::Vector3d initial_rate{0, 0, 2 * 3.14159265358979323846 / 180};  // ω(0), rad/s
  double orbit_rate = 1.1016e-3;     // n, rad/s
  double mu = 3.986004418e14;        // m³/s²
  // servicer
  double servicer_mass = 500.0;      // kg
  Eigen::Vector3d hold_point{3, 0, 0};        // ρ*, m
  Eigen::Vector3d initial_offset{1, -1, 0.5}; // ρ(0) − ρ*, m
  Eigen::Vector3d initial_velocity = Eigen::Vector3d::Zero();  // ρ̇(0) in t, m/s
  double measurement_sigma = 0.01;   // camera position noise, m per axis
  // control
  bool feedforward = true;                      // U* of docs/maths.md (158)
  // U* from the target's current ω, ω̇ at each control sample (feedforward: {from: target_rate}):
  // the rate the camera's relative attitude gives, here the truth's; else from nominal_rate.
  bool feedforward_from_target_rate = false;
  Eigen::Vector3d nominal_rate{0, 0, 2 * 3.14159265358979323846 / 180};  // ω₀ of U*, rad/s
  Eigen::Vector3d nominal_accel = Eigen::Vector3d::Zero();                 // ω̇₀ of U*, rad/s²
  ControllerSource controller;
  hinf::runtime::ThrusterSettings thrusters;
  ModulatorKind modulator = ModulatorKind::Pwm;
  hinf::runtime::PwmSettings pwm;
  hinf::runtime::PwpfSettings pwpf;
  // metrics
  double steady_state_start = 600.0;  // s
  double settle_threshold = 0.05;     // m, on |ρ − ρ*|
  bool plots = true;

  long control_steps() const;      // samples t_k = k T_c, k = 0 … duration/T_c
  long ticks_per_control() const;  // T_c / integration_step
};

// The most integration steps a run may take (1e8: 28 hours at 1 ms; a run of this size
// takes about a minute on the development machine).
constexpr double kMaxIntegrationSteps = 1e8;

// Why s.duration needs too many integration steps (more than kMaxIntegrationSteps of
// s.integration_step), or "" if it does not.
std::string integration_problem(const HoldScenario& s);

// hinf-sim --duration D on a hold scenario: D must be a run of control samples
// (checked_duration, sim/scenario.hpp) and of at most kMaxIntegrationSteps integration steps;
// else Error(InvalidInput) naming --duration. A steady-state window that would start after
// the shorter run starts at its middle.
void set_hold_duration(HoldScenario& s, double duration);

}  // namespace hinf::sim
