// simulate_hold_run (hold_run.hpp).
#include "hinf/sim/hold_run.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "hinf/common/number_text.hpp"
#include "hinf/models/tumbling_hold.hpp"
#include "hinf/runtime/lti_controller.hpp"
#include "hinf/sim/hold_truth.hpp"
#include "hinf/sim/rng.hpp"
#include "hinf/sim/run.hpp"

namespace hinf::sim {
namespace {

// The thrusters of the three axes behind their modulator: command() at each control
// sample, then sign() over each integration tick, advance() after it.
class Thrusters {
 public:
  explicit Thrusters(const HoldScenario& s)
      : kind_(s.modulator),
        force_(s.thrusters.force),
        dt_(s.integration_step),
        samples_per_period_(std::lround(s.pwm.period / s.control_sample_time)),
        ticks_per_control_(s.ticks_per_control()) {
    for (int i = 0; i < 3; ++i) {
      pwm_[i] = hinf::runtime::PwmModulator(s.pwm);
      pwpf_[i] = hinf::runtime::PwpfModulator(s.pwpf);
    }
  }

  // The command U (N) of control sample k.
  void command(long k, const Eigen::Vector3d& U) {
    U_ = U;
    if (kind_ == ModulatorKind::Pwm && k % samples_per_period_ == 0) {
      for (int i = 0; i < 3; ++i) pulse_[i] = pwm_[i].begin_period(U(i));
      period_tick_ = 0;
    }
  }

  // The applied force over the current tick, N.
  Eigen::Vector3d force() const {
    Eigen::Vector3d F;
    for (int i = 0; i < 3; ++i)
      F(i) = kind_ == ModulatorKind::Ideal ? std::clamp(U_(i), -force_, force_) : force_ * sign(i);
    return F;
  }
  // The thruster's state over the current tick (−1, 0, +1); the ideal actuator's sign of force.
  int sign(int i) const {
    switch (kind_) {
      case ModulatorKind::Pwm: return pulse_[i].output_at_tick(period_tick_);
      case ModulatorKind::Pwpf: return pwpf_[i].output();
      default: return U_(i) > 0 ? 1 : U_(i) < 0 ? -1 : 0;
    }
  }
  void advance() {
    ++period_tick_;
    if (kind_ == ModulatorKind::Pwpf)
      for (int i = 0; i < 3; ++i) pwpf_[i].step(U_(i), dt_);
  }

 private:
  ModulatorKind kind_;
  double force_, dt_;
  long samples_per_period_, ticks_per_control_;
  std::array<hinf::runtime::PwmModulator, 3> pwm_;
  std::array<hinf::runtime::PwpfModulator, 3> pwpf_;
  std::array<hinf::runtime::PwmModulator::Pulse, 3> pulse_{};
  long period_tick_ = 0;
  Eigen::Vector3d U_ = Eigen::Vector3d::Zero();
};

// Pulses per axis: their number and the shortest completed one (in ticks).
class PulseCounter {
 public:
  void tick(int axis, int sign) {
    int& last = last_[axis];
    long& length = length_[axis];
    if (sign != last && last != 0) finish(length);
    if (sign != 0) {
      if (sign != last) {
        ++count_;
        length = 0;
      }
      ++length;
    }
    last = sign;
  }
  long count() const { return count_; }
  std::optional<long> shortest() const { return shortest_; }

 private:
  void finish(long length) { shortest_ = shortest_ ? std::min(*shortest_, length) : length; }
  std::array<int, 3> last_{};
  std::array<long, 3> length_{};
  long count_ = 0;
  std::optional<long> shortest_;
};

// A finite truth whose metrics overflow (errors of 1e200 m squared in an RMS) cannot be
// summarised: SimulationError naming the metric, never a summary with inf in it.
void require_finite_metrics(const HoldMetrics& m) {
  const std::pair<const char*, double> values[] = {{"position_rms_m", m.position_rms_m},
                                                   {"position_max_m", m.position_max_m},
                                                   {"velocity_rms_mps", m.velocity_rms_mps},
                                                   {"delta_v_mps", m.delta_v_mps}};
  for (const auto& [name, value] : values)
    if (!std::isfinite(value))
      throw SimulationError(std::string("tumbling_hold: the metric ") + name + " is " + number_text(value) +
                            ": the run's errors or forces are beyond floating-point range (check the scenario's "
                            "servicer_mass, hold_point, initial_offset and initial_velocity)");
}

HoldMetrics window_metrics(const HoldScenario& s, const HoldTrajectory& tr) {
  HoldMetrics m;
  Eigen::Vector3d sum_e2 = Eigen::Vector3d::Zero(), sum_v2 = Eigen::Vector3d::Zero();
  long count = 0;
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    if (tr.t[k] < s.steady_state_start) continue;
    sum_e2 += tr.error[k].cwiseAbs2();
    sum_v2 += tr.velocity[k].cwiseAbs2();
    m.position_max_m = std::max(m.position_max_m, tr.error[k].cwiseAbs().maxCoeff());
    ++count;
  }
  m.position_rms_m = std::sqrt(sum_e2.maxCoeff() / static_cast<double>(count));
  m.velocity_rms_mps = std::sqrt(sum_v2.maxCoeff() / static_cast<double>(count));
  long last_outside = -1;
  for (std::size_t k = 0; k < tr.t.size(); ++k)
    if (!(tr.error[k].norm() < s.settle_threshold)) last_outside = static_cast<long>(k);
  if (last_outside + 1 < static_cast<long>(tr.t.size())) m.settle_time_s = tr.t[static_cast<std::size_t>(last_outside + 1)];
  return m;
}

}  // namespace

double hold_trace_window(const HoldScenario& s) { return s.duration / kPlotWindowsPerRun; }

std::vector<std::vector<double>> hold_error_norms(const HoldTrajectory& tr) {
  std::vector<std::vector<double>> norms(2);
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    norms[0].push_back(tr.error[k].norm());
    norms[1].push_back(tr.velocity[k].norm());
  }
  return norms;
}

HoldRunResult simulate_hold_run(const HoldSetup& setup, std::uint64_t run_seed, bool keep_trajectory) {
  const HoldScenario& s = setup.scenario;
  const HoldTruth truth(s);
  HoldTruthVector y = truth.initial_state(s);
  hinf::runtime::LtiController controller(setup.controller.A_K, setup.controller.B_K, setup.controller.C_K,
                                          setup.controller.D_K);
  Thrusters thrusters(s);
  PulseCounter pulses;
  Rng camera(derive_seed(run_seed, 0));
  const long steps = s.control_steps(), ticks = s.ticks_per_control();
  const double h = s.integration_step;
  HoldTrajectory tr;
  HoldMetrics totals;
  long saturated = 0;
  Eigen::VectorXd e(3);
  for (long k = 0; k < steps; ++k) {
    const double t_k = static_cast<double>(k) * s.control_sample_time;
    if (!y.allFinite())
      throw SimulationError("tumbling_hold: the truth became non-finite at t = " + std::to_string(t_k) + " s");
    tr.t.push_back(t_k);
    tr.error.push_back(y.segment<3>(0) - s.hold_point);
    tr.velocity.push_back(y.segment<3>(3));
    const bool last = k + 1 == steps;
    Eigen::Vector3d U = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    if (!last) {
      for (int i = 0; i < 3; ++i) e(i) = y(i) + s.measurement_sigma * camera.normal() - s.hold_point(i);
      const Eigen::Vector3d U_star =
          s.feedforward_from_target_rate
              ? hinf::models::equilibrium_force(s.servicer_mass, y.segment<3>(10), truth.omega_dot(y.segment<3>(10)),
                                                s.hold_point)
              : setup.feedforward;
      U = U_star + controller.step(e);
      if (U.cwiseAbs().maxCoeff() > s.thrusters.force) ++saturated;
      thrusters.command(k, U);
    }
    tr.command.push_back(U);
    tr.pulse.emplace_back(thrusters.sign(0), thrusters.sign(1), thrusters.sign(2));
    Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
    for (long j = 0; j < ticks && !last; ++j) {
      const Eigen::Vector3d F = thrusters.force();
      for (int i = 0; i < 3; ++i) pulses.tick(i, s.modulator == ModulatorKind::Ideal ? 0 : thrusters.sign(i));
      impulse += F * h;
      totals.delta_v_mps += F.cwiseAbs().sum() * h / s.servicer_mass;
      truth.step(y, t_k + static_cast<double>(j) * h, F, h);
      thrusters.advance();
    }
    tr.force.push_back(last ? Eigen::Vector3d::Zero() : Eigen::Vector3d(impulse / s.control_sample_time));
  }
  HoldRunResult r;
  r.seed = run_seed;
  r.metrics = window_metrics(s, tr);
  r.metrics.delta_v_mps = totals.delta_v_mps;
  r.metrics.pulse_count = pulses.count();
  if (pulses.shortest()) r.metrics.min_pulse_s = static_cast<double>(*pulses.shortest()) * h;
  r.metrics.saturation_fraction = static_cast<double>(saturated) / static_cast<double>(steps - 1);
  require_finite_metrics(r.metrics);
  r.traces = run_traces({tr.t}, {hold_error_norms(tr)}, hold_trace_window(s));
  if (keep_trajectory) r.trajectory = std::move(tr);
  return r;
}

}  // namespace hinf::sim
