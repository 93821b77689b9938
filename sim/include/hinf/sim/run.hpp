// One simulation run: nonlinear truth, sensor, thrust and the selected filters, stepped
// together on one measurement stream (step order in estimator.hpp).
#pragma once
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hinf/sim/estimator.hpp"
#include "hinf/sim/metrics.hpp"
#include "hinf/sim/scenario.hpp"
#include "hinf/sim/simulation_error.hpp"
#include "hinf/sim/vectors.hpp"

namespace hinf::sim {

// Gains of an LTI filter (docs/maths.md (5)–(6)), obtained once before the runs (gains_source.hpp).
// Everything the runs share, prepared once.
struct RunSetup {
  Scenario scenario;
  std::optional<LtiGains> hinf, published;
};

// Noise stream indices inside a run: stream seed = derive_seed(run seed, index).
enum NoiseStream : std::uint64_t { kProcessX = 0, kProcessY, kProcessZ, kRange, kAzimuth, kElevation };

struct FilterTrack {
  std::string name;
  std::vector<Vector6> estimate;  // one per step; NaN after divergence
  std::optional<long> diverged_at;
  FilterHealth health;
};

struct Trajectory {
  std::vector<double> t;
  std::vector<Vector6> truth;
  std::vector<MeasurementSample> measurement;
  std::vector<Vector3> thrust;  // u(k), N, applied over [t_k, t_{k+1})
  std::vector<FilterTrack> filters;
};

struct FilterOutcome {
  std::string name;
  FilterMetrics metrics;
  FilterHealth health;
  // The plots' traces (plot_trace_settings): the moving RMS of |e_p| and |e_v| at RunResult::trace_t.
  std::vector<double> position_rms_trace, velocity_rms_trace;
};

// Every run keeps its error norms' moving RMS over `window` samples at every `stride`-th sample
// (at most kPlotTracePoints of them) for the Monte-Carlo band of the plots (docs/experiments.md
// "Plots"); window: metrics.converge_window_s when set, else 1 % of the duration.
inline constexpr long kPlotTracePoints = 600;
inline constexpr double kPlotWindowsPerRun = 100;  // the window when the scenario sets none: duration / 100
struct PlotTraceSettings {
  double window_s = 0;
  long stride = 1;  // samples
};
PlotTraceSettings plot_trace_settings(const Scenario& s);

struct RunResult {
  std::uint64_t seed = 0;
  std::vector<double> trace_t;           // s: the instants of the filters' plot traces
  std::vector<FilterOutcome> filters;    // in the order of filter_names()
  std::optional<Trajectory> trajectory;  // kept if asked for
};

// hinf, published, ekf, ekf_no_control, rekf — those selected, in this order.
std::vector<std::string> filter_names(const Scenario& scenario);

RunResult simulate_run(const RunSetup& setup, std::uint64_t run_seed, bool keep_trajectory);

}  // namespace hinf::sim
