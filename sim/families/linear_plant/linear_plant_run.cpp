// One run of a linear_plant experiment and the predicted RMS (linear_plant_run.hpp,
// docs/maths.md §33).
#include "hinf/sim/linear_plant_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "hinf/certify/h2_norm.hpp"
#include "hinf/common/error.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/sim/rng.hpp"
#include "hinf/sim/simulation_error.hpp"

namespace hinf::sim {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// The noise streams of a run, one per channel (docs/experiments.md "Reproducibility").
enum Stream : std::uint64_t { kProcessStream = 0, kMeasurementStream = 1, kInitialStateStream = 2, kUncertaintyStream = 3 };

VectorXd normal_vector(Rng& rng, Eigen::Index size, double std) {
  VectorXd v(size);
  for (Eigen::Index i = 0; i < size; ++i) v(i) = std * rng.normal();
  return v;
}

struct FilterRun {
  std::unique_ptr<runtime::LtiFilter> filter;
  double sum_squares = 0, max_error = 0;
  long count = 0;
  bool diverged = false;
};

}  // namespace

int LinearPlantScenario::uncertainty_blocks() const {
  if (!truth_parameters.empty()) return static_cast<int>(truth_parameters.size());
  return plant.uncertain() ? static_cast<int>(plant.F_block_ranges().size()) : 0;
}

MatrixXd LinearPlantScenario::truth_A(const VectorXd& delta) const {
  if (!plant.uncertain()) return plant.A;
  MatrixXd F = MatrixXd::Zero(plant.j(), plant.k());
  if (!truth_parameters.empty()) {  // diag(δᵢ I_{sᵢ}) over the parameters' columns (138)
    Eigen::Index at = 0;
    for (std::size_t i = 0; i < truth_parameters.size(); ++i) {
      const Eigen::Index s = truth_parameters[i].columns;
      F.block(at, at, s, s).diagonal().setConstant(delta(static_cast<Eigen::Index>(i)));
      at += s;
    }
    return plant.A + plant.H * F * plant.E;
  }
  Eigen::Index b = 0;
  for (const auto& [at, size] : plant.F_block_ranges()) {  // structured: square blocks; else one j×k Ē
    const Eigen::Index rows = plant.structured() ? size : plant.j(), cols = plant.structured() ? size : plant.k();
    F.block(at, at, rows, cols) = delta(b++) * MatrixXd::Identity(rows, cols);
  }
  return plant.A + plant.H * F * plant.E;
}

namespace {

// The run's δ per scalar: per named parameter (pᵢ − νᵢ)/rᵢ at its value or at one drawn on its
// range; per block the scenario's one value, or each uniform on [−1, 1].
VectorXd draw_delta(const LinearPlantScenario& s, std::uint64_t seed) {
  Rng rng(derive_seed(seed, kUncertaintyStream));
  if (!s.truth_parameters.empty()) {
    VectorXd delta(s.uncertainty_blocks());
    for (Eigen::Index i = 0; i < delta.size(); ++i) {
      const TruthParameter& p = s.truth_parameters[static_cast<std::size_t>(i)];
      const double value = p.value ? *p.value : p.low + (p.high - p.low) * rng.uniform01();
      delta(i) = (value - p.nominal) / p.radius;
    }
    return delta;
  }
  VectorXd delta = VectorXd::Constant(s.uncertainty_blocks(), s.uncertainty_delta);
  if (!s.random_uncertainty) return delta;
  for (Eigen::Index b = 0; b < delta.size(); ++b) delta(b) = 2 * rng.uniform01() - 1;
  return delta;
}

}  // namespace

double predicted_error_rms(const LinearPlantScenario& s, const LtiGains& g, const VectorXd& delta) {
  const Plant& P = s.plant;
  const Eigen::Index n = P.n(), nf = g.A_F.rows(), p = P.p(), q = P.q();
  const bool filtered = g.D_F.size() > 0;
  // (228) with the noise scaled to unit covariance: ξ = [x; x_F], ξ(k+1) = Ā ξ + B̄ n,
  // e = C̄ ξ + D̄ n, n = [w/σ_w; v/σ_v]; (229) is its H2 norm.
  StateSpace e{MatrixXd::Zero(n + nf, n + nf), MatrixXd::Zero(n + nf, p + q), MatrixXd(P.l(), n + nf),
               MatrixXd::Zero(P.l(), p + q)};
  e.A.topLeftCorner(n, n) = s.truth_A(delta);
  e.A.bottomLeftCorner(nf, n) = g.B_F * P.C;
  e.A.bottomRightCorner(nf, nf) = g.A_F;
  e.B.topLeftCorner(n, p) = s.process_std * P.B;
  e.B.bottomRightCorner(nf, q) = s.measurement_std * g.B_F * P.D;
  e.C << (filtered ? MatrixXd(P.L - g.D_F * P.C) : P.L), -g.C_F;
  if (filtered) e.D.rightCols(q) = -s.measurement_std * g.D_F * P.D;
  try {
    return certify::discrete_h2_norm(e);
  } catch (const Error&) {  // not Schur stable, or the Gramian did not converge: no stationary value
    return std::numeric_limits<double>::quiet_NaN();
  }
}

std::vector<LinearPlantStatistics> run_linear_plant(const LinearPlantScenario& s,
                                                    const std::vector<LinearPlantFilter>& filters,
                                                    const LinearPlantRunOptions& o, std::uint64_t seed) {
  const Plant& P = s.plant;
  const VectorXd delta = draw_delta(s, seed);
  const MatrixXd A = s.truth_A(delta);
  Rng process(derive_seed(seed, kProcessStream)), measurement(derive_seed(seed, kMeasurementStream));
  Rng initial(derive_seed(seed, kInitialStateStream));
  VectorXd x = normal_vector(initial, P.n(), s.initial_state_std);
  std::vector<FilterRun> runs(filters.size());
  for (std::size_t f = 0; f < filters.size(); ++f) {
    const LtiGains& g = filters[f].gains;
    runs[f].filter = std::make_unique<runtime::LtiFilter>(g.A_F, g.B_F, g.C_F, MatrixXd::Zero(g.A_F.rows(), 0),
                                                          g.D_F.size() > 0 ? g.D_F : MatrixXd(0, 0));
  }
  const long samples = std::lround(s.duration / s.sample_time);
  LinearPlantSample sample;
  for (long k = 0; k <= samples; ++k) {
    const double t = static_cast<double>(k) * s.sample_time;
    require_finite_truth("linear_plant", k, t, x, {{"x", 0, P.n()}});
    const VectorXd y = P.C * x + P.D * normal_vector(measurement, P.q(), s.measurement_std);
    const VectorXd z = P.L * x;
    for (std::size_t f = 0; f < filters.size(); ++f) {
      FilterRun& r = runs[f];
      const VectorXd& z_hat = r.filter->step(y);
      const double error = (z - z_hat).norm();
      if (!r.diverged && !std::isfinite(error)) r.diverged = true;
      if (!r.diverged && t >= o.window_start) {
        r.sum_squares += error * error;
        r.max_error = std::max(r.max_error, error);
        ++r.count;
      }
      if (o.on_sample) {
        sample.t = t;
        sample.z = z;
        sample.z_hat = z_hat;
        o.on_sample(static_cast<int>(f), sample);
      }
    }
    x = A * x + P.B * normal_vector(process, P.p(), s.process_std);
  }
  std::vector<LinearPlantStatistics> out(filters.size());
  for (std::size_t f = 0; f < filters.size(); ++f) {
    out[f].delta = delta;
    out[f].predicted_rms = predicted_error_rms(s, filters[f].gains, delta);
    out[f].diverged = runs[f].diverged;
    if (runs[f].diverged || runs[f].count == 0) continue;
    out[f].error_rms = std::sqrt(runs[f].sum_squares / static_cast<double>(runs[f].count));
    out[f].error_max = runs[f].max_error;
  }
  return out;
}

}  // namespace hinf::sim
