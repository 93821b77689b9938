// `scenario: linear_plant` (docs/experiments.md "The user's own plant"): the plant of the
// user's synthesis config, driven by white noise, and LTI filters of it side by side — the
// H∞ filter (synthesised now or from a gains file) and the Kalman one-step predictor —
// each filter's estimate error z − ẑ over the runs against its predicted steady-state RMS
// (docs/maths.md §33).
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hinf/models/plant.hpp"
#include "hinf/sim/estimator.hpp"

namespace hinf::sim {

// A named parameter of the config in the truth (`truth.parameters`, docs/maths.md §33): its
// value pᵢ, or drawn per run uniformly on its range; δᵢ = (pᵢ − νᵢ)/rᵢ scales its columns of H (137).
struct TruthParameter {
  std::string name;
  double nominal = 0, radius = 1, low = 0, high = 0;  // νᵢ, rᵢ, its range
  int columns = 0;                                    // sᵢ: its columns of H (138)
  std::optional<double> value;                        // pᵢ; unset: drawn per run in [low, high]
};

// The truth, docs/maths.md (227): x(k+1) = A_δ x(k) + B w(k), y(k) = C x(k) + D v(k),
// z(k) = L x(k), with w(k) ~ N(0, σ_w² I_p), v(k) ~ N(0, σ_v² I_q), x(0) ~ N(0, σ_0² I_n) and
// A_δ = A + H F_δ E. Without `truth.parameters`, F_δ = diag(δ_b Ē_b) over F's blocks b (Ē_b:
// ones on its diagonal; one block j×k when F is not structured), every |δ_b| ≤ 1: one δ for
// all blocks, or each drawn per run uniformly on [−1, 1]. With it, F_δ = diag(δᵢ I_{sᵢ}) over
// the named parameters that enter A (§22), each at its value. A known input (G) is zero.
struct LinearPlantScenario {
  Plant plant;              // the config's, discrete (sampled by the config if given in continuous time)
  std::string config_path;  // resolved
  double sample_time = 1;   // s: the config's, or 1 if it states none (time then counts samples)
  double duration = 0;      // s, a whole number of samples
  double process_std = 1, measurement_std = 1, initial_state_std = 0;  // σ_w, σ_v, σ_0
  double uncertainty_delta = 0;                                       // δ of every block …
  bool random_uncertainty = false;                                    // … or each δ_b drawn per run
  std::vector<TruthParameter> truth_parameters;                       // … or δ per named parameter
  int uncertainty_blocks() const;        // the run's δ scalars: parameters, else F's blocks (0: certain)
  Eigen::MatrixXd truth_A(const Eigen::VectorXd& delta) const;        // A_δ, δ: one per scalar
};

// One filter of the experiment and where its gains come from.
struct LinearPlantFilter {
  std::string name;
  std::string type;             // "hinf" or "kalman"
  LtiGains gains;               // (5)–(6), with D_F for a filtered estimate (140)
  std::optional<double> gamma;  // the certified H∞ bound of the gains
  std::string origin;           // "gains file P", "synthesised from P", "Kalman predictor of P"
  std::string gains_yaml;       // the gains file (written to the run directory as <name>_gains.yaml)
};

// Run 0, one filter, sample k: the truth's z(k) and the filter's ẑ(k).
struct LinearPlantSample {
  double t = 0;
  Eigen::VectorXd z, z_hat;
};

// One filter in one run, over the steady-state window: the RMS and the largest of |z − ẑ|
// (Euclidean over the l entries), NaN once the filter's estimate became non-finite; the RMS
// predicted for the run's truth (229), NaN if not stationary; the run's δ per scalar.
struct LinearPlantStatistics {
  double error_rms = std::numeric_limits<double>::quiet_NaN();
  double error_max = std::numeric_limits<double>::quiet_NaN();
  double predicted_rms = std::numeric_limits<double>::quiet_NaN();
  bool diverged = false;
  Eigen::VectorXd delta;
};

struct LinearPlantRunOptions {
  double window_start = 0;  // s: the steady-state window is [window_start, duration]
  std::function<void(int, const LinearPlantSample&)> on_sample;  // (filter index, sample); run 0
};

// One run of every filter on one noise stream with `seed`. Throws SimulationError if the truth
// becomes non-finite (an unstable plant run for long).
std::vector<LinearPlantStatistics> run_linear_plant(const LinearPlantScenario& s,
                                                    const std::vector<LinearPlantFilter>& filters,
                                                    const LinearPlantRunOptions& o, std::uint64_t seed);

// The steady-state RMS of z − ẑ for these gains on the scenario's truth at `delta` (one per
// scalar) and its noise, docs/maths.md (229): the H2 norm of (228) with the noise scaled to unit
// covariance (certify::discrete_h2_norm); NaN if (228) is not Schur stable.
double predicted_error_rms(const LinearPlantScenario& s, const LtiGains& gains, const Eigen::VectorXd& delta);

}  // namespace hinf::sim
