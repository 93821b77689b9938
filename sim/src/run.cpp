#include "hinf/sim/run.hpp"

#include <hinf/models/range_azimuth_elevation.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "hinf/sim/noise.hpp"
#include "hinf/sim/rng.hpp"

namespace hinf::sim {

std::vector<std::string> filter_names(const Scenario& s) {
  std::vector<std::string> names;
  if (s.filters.hinf) names.push_back("hinf");
  if (s.filters.published) names.push_back("published");
  if (s.filters.ekf) names.push_back("ekf");
  if (s.filters.ekf_no_control) names.push_back("ekf_no_control");
  if (s.filters.rekf) names.push_back("rekf");
  return names;
}

namespace {

// The filters of the scenario, in filter_names() order.
std::vector<std::unique_ptr<Estimator>> make_estimators(const RunSetup& setup) {
  const Scenario& s = setup.scenario;
  std::vector<std::unique_ptr<Estimator>> estimators;
  if (s.filters.hinf) estimators.push_back(make_lti_estimator(*setup.hinf, s.initial_estimate));
  if (s.filters.published)
    estimators.push_back(make_lti_estimator(*setup.published, s.initial_estimate));
  if (s.filters.ekf) estimators.push_back(make_ekf_estimator(s, kalman_settings_from(s, true)));
  if (s.filters.ekf_no_control) estimators.push_back(make_ekf_estimator(s, kalman_settings_from(s, false)));
  if (s.filters.rekf) estimators.push_back(make_rekf_estimator(s, kalman_settings_from(s, true), *s.filters.rekf));
  return estimators;
}

// The seeded noise streams of one run (docs/maths.md §14).
struct RunNoise {
  RunNoise(const Scenario& s, std::uint64_t run_seed)
      : process{NoiseChannel(s.process_noise, s.sample_time, s.steps(), derive_seed(run_seed, kProcessX)),
                NoiseChannel(s.process_noise, s.sample_time, s.steps(), derive_seed(run_seed, kProcessY)),
                NoiseChannel(s.process_noise, s.sample_time, s.steps(), derive_seed(run_seed, kProcessZ))},
        range(s.range_noise, s.sample_time, s.steps(), derive_seed(run_seed, kRange)),
        azimuth(s.azimuth_noise, s.sample_time, s.steps(), derive_seed(run_seed, kAzimuth)),
        elevation(s.elevation_noise, s.sample_time, s.steps(), derive_seed(run_seed, kElevation)) {}
  NoiseChannel process[3];
  NoiseChannel range, azimuth, elevation;
};

// The run's recorded series, sized once.
// What a run records: the error norms (the metrics') and the instants always; the truth,
// measurements, thrust and estimates only when the trajectory is kept (run 0).
struct RunRecord {
  RunRecord(const std::vector<std::string>& names, long steps, bool keep_trajectory)
      : keep(keep_trajectory), pos_err(names.size()), vel_err(names.size()) {
    const auto n = static_cast<std::size_t>(steps);
    traj.t.reserve(n);
    traj.filters.resize(names.size());
    for (std::size_t f = 0; f < names.size(); ++f) {
      traj.filters[f].name = names[f];
      pos_err[f].reserve(n);
      vel_err[f].reserve(n);
      if (keep) traj.filters[f].estimate.reserve(n);
    }
    if (!keep) return;
    traj.truth.reserve(n);
    traj.measurement.reserve(n);
    traj.thrust.reserve(n);
  }
  bool keep;
  Trajectory traj;
  std::vector<std::vector<double>> pos_err, vel_err;
};

// Thrust u(k) = K x̂(k) (docs/maths.md (66)), held over the sample; x̂ is the truth or the
// hinf estimate, as the scenario says.
Vector3 thrust(const Scenario& s, const Vector6& x, const Vector6& hinf_estimate, double t) {
  if (s.control_law != ControlLaw::StateFeedback) return Vector3::Zero();
  const Vector6& xc = s.control_input == ControlInput::Truth ? x : hinf_estimate;
  if (!xc.allFinite())
    throw SimulationError("thrust from the hinf estimate is undefined at t = " + std::to_string(t) +
                          " s: the hinf filter diverged");
  return s.K * xc;
}

}  // namespace

PlotTraceSettings plot_trace_settings(const Scenario& s) {
  PlotTraceSettings p;
  p.window_s = s.converge_window_s > 0 ? s.converge_window_s : s.duration / kPlotWindowsPerRun;
  p.stride = std::max(1L, (s.steps() + kPlotTracePoints - 1) / kPlotTracePoints);
  return p;
}

RunResult simulate_run(const RunSetup& setup, std::uint64_t run_seed, bool keep_trajectory) {
  const Scenario& s = setup.scenario;
  const long steps = s.steps();
  const double T = s.sample_time;

  // Truth: the exact two-body relative motion about a target whose rate is ω₀(1+δ).
  const RelativeTwoBody truth_model(s.mu, s.orbital_rate * (1.0 + s.truth_delta));
  const hinf::models::RangeAzimuthElevation sensor(s.C_bl);
  RunNoise noise(s, run_seed);
  const std::vector<std::unique_ptr<Estimator>> estimators = make_estimators(setup);
  const std::vector<std::string> names = filter_names(s);
  const std::size_t nf = estimators.size();
  RunRecord rec(names, steps, keep_trajectory);
  const std::size_t hinf_index =  // the filter whose estimate the thrust may use (nf: none)
      static_cast<std::size_t>(std::find(names.begin(), names.end(), "hinf") - names.begin());
  Trajectory& traj = rec.traj;
  const Vector6 nan6 = Vector6::Constant(std::numeric_limits<double>::quiet_NaN());

  Vector6 x = s.initial_state;
  for (long k = 0; k < steps; ++k) {
    const double t = k * T;
    if (!x.allFinite()) throw SimulationError("truth state became non-finite at t = " + std::to_string(t) + " s");

    // Sensor: ρ, α, β of the true position (C_bl applied), noise added, converted back.
    MeasurementSample y;
    y.rae = sensor.h(x) + Vector3(noise.range.next(), noise.azimuth.next(), noise.elevation.next());
    y.cartesian = sensor.position_from_measurement(y.rae);
    y.jacobian = sensor.conversion_jacobian(y.rae);

    Vector6 hinf_estimate = nan6;
    for (std::size_t f = 0; f < nf; ++f) {
      FilterTrack& track = traj.filters[f];
      Vector6 e = nan6;
      if (!track.diverged_at) {
        e = estimators[f]->estimate(y, t);
        const double ep = (e.head<3>() - x.head<3>()).norm();
        if (!e.allFinite() || !(ep <= s.divergence_limit_m)) {
          track.diverged_at = k;
          e = nan6;
        }
      }
      if (f == hinf_index) hinf_estimate = e;
      if (rec.keep) track.estimate.push_back(e);
      rec.pos_err[f].push_back((e.head<3>() - x.head<3>()).norm());
      rec.vel_err[f].push_back((e.tail<3>() - x.tail<3>()).norm());
    }
    const Vector3 u = thrust(s, x, hinf_estimate, t);
    traj.t.push_back(t);
    if (rec.keep) {
      traj.truth.push_back(x);
      traj.measurement.push_back(y);
      traj.thrust.push_back(u);
    }
    for (std::size_t f = 0; f < nf; ++f)
      if (!traj.filters[f].diverged_at) estimators[f]->advance(u, t);

    // Truth from t_k to t_{k+1}: thrust and process acceleration held (zero-order hold).
    const Vector3 accel =
        u / s.chaser_mass + Vector3(noise.process[0].next(), noise.process[1].next(), noise.process[2].next());
    x = truth_model.propagate(x, accel, T, s.integrator_substeps);
  }

  RunResult result;
  result.seed = run_seed;
  const MetricSettings ms = s.metric_settings();
  const PlotTraceSettings plot = plot_trace_settings(s);
  for (long k = 0; k < steps; k += plot.stride) result.trace_t.push_back(traj.t[static_cast<std::size_t>(k)]);
  for (std::size_t f = 0; f < nf; ++f) {
    traj.filters[f].health = estimators[f]->health();
    result.filters.push_back(
        {names[f], compute_metrics(traj.t, rec.pos_err[f], rec.vel_err[f], traj.filters[f].diverged_at, ms),
         estimators[f]->health(), moving_rms_samples(traj.t, rec.pos_err[f], plot.window_s, plot.stride),
         moving_rms_samples(traj.t, rec.vel_err[f], plot.window_s, plot.stride)});
  }
  if (keep_trajectory) result.trajectory = std::move(traj);
  return result;
}

}  // namespace hinf::sim
