// The filters compared in a run, behind one interface, all fed the same measurement
// stream. The filters themselves are hinf::runtime's (LtiFilter, Ekf, Rekf); this file
// only adapts them to the simulation's step order:
//
//   row k:  y(k) measured → every filter's estimate of x(k) → thrust u(k) → advance(u(k))
//
// What "estimate of x(k)" is (docs/experiments.md, "Trajectory file"):
//   LTI filters (hinf, published): z_F(k) = C_F x_F(k), from y(0..k−1) (docs/maths.md §2.2:
//     the filter (5)–(6) is a one-step predictor); y(k) is consumed afterwards, x_F(k+1) = A_F x_F(k) + B_F y(k).
//   EKF / REKF: the filtered x̂(k|k), from y(0..k); advance() predicts to k+1 with u(k).
#pragma once
#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>

#include "hinf/sim/scenario.hpp"
#include "hinf/sim/vectors.hpp"

namespace hinf::sim {

// One sample of the sensor: the raw (ρ, α, β) and the converted Cartesian position
// (docs/maths.md (82)), which is what every filter receives.
struct MeasurementSample {
  Vector3 rae;        // ρ (m), α (rad), β (rad), noisy
  Vector3 cartesian;  // C_blᵀ (ρ cosβ cosα, ρ cosβ sinα, −ρ sinβ)
  Eigen::Matrix3d jacobian;  // d cartesian / d rae at rae (the Kalman filters' R; computed once a step)
};

// Steps on which a runtime filter reported a non-ok status (it then skips that step).
struct FilterHealth {
  long failed_steps = 0;
  std::string first_failure;   // the runtime's status text
  double first_failure_t = 0;  // s
};

class Estimator {
 public:
  virtual ~Estimator() = default;
  // The estimate of x(k) logged in row k (see above).
  virtual Vector6 estimate(const MeasurementSample& y, double t) = 0;
  // The thrust u(k) (N) applied over [t_k, t_{k+1}).
  virtual void advance(const Vector3& thrust, double t) = 0;
  const FilterHealth& health() const { return health_; }

 protected:
  void record(bool ok, const char* status, double t) {
    if (ok) return;
    if (health_.failed_steps++ == 0) {
      health_.first_failure = status;
      health_.first_failure_t = t;
    }
  }
  FilterHealth health_;
};

// A fixed-gain filter's realisation (docs/maths.md (5)–(6)).
struct LtiGains {
  Matrix A_F, B_F, C_F;
  Matrix D_F;  // l×m feedthrough of a filtered estimate (docs/maths.md (140)); empty: none
};

// The filter docs/maths.md (5)–(6) (with D_F: (140)) with x_F(0) = C_F⁺ z0, (8) (L = I).
std::unique_ptr<Estimator> make_lti_estimator(const LtiGains& gains, const Vector6& z0);

// EKF on the Hill/CW model (nominal ω₀, exact zero-order-hold discretisation) with the
// Cartesian position measurement:
//   Q = σ_a² G Gᵀ, G = [T²/2·I₃; T·I₃]  (σ_a² = process-noise variance per axis),
//   R(k) = J(k) diag(σ_ρ², σ_α², σ_β²) J(k)ᵀ + r_floor·I  (J = ∂position/∂(ρ,α,β) at the measured ρ, α, β).
// knows_thrust: predicts with the applied thrust; otherwise with u = 0.
struct KalmanSettings {
  double acceleration_variance = 0;  // σ_a², (m/s²)²
  double range_variance = 0, azimuth_variance = 0, elevation_variance = 0;
  double r_floor = 1e-8;             // m², keeps R positive definite at tiny range
  bool knows_thrust = true;
};
KalmanSettings kalman_settings_from(const Scenario& scenario, bool knows_thrust);

std::unique_ptr<Estimator> make_ekf_estimator(const Scenario& scenario, const KalmanSettings& settings);

// The REKF of docs/maths.md §13, same model as the EKF, told about the orbital-rate uncertainty
// |δ| ≤ δ̄ through A_k = T·H_a, L = E_a(δ̄) (docs/maths.md (100)), C_k = 0; knows the thrust.
std::unique_ptr<Estimator> make_rekf_estimator(const Scenario& scenario, const KalmanSettings& settings,
                                               const RekfSettings& rekf);

}  // namespace hinf::sim
