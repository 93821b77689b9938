// Relative GPS/INS navigation of a chaser flying around a target (docs/maths.md §29): the
// 15-state model of the error-state EKF/REKF and its 19-row measurement model.
//
//   x = [ρ (LVLH R, m); ρ̇ (m/s); σ (MRP of B relative to F); ω (rad/s, B relative to F, in B);
//        b (gyro bias, rad/s)],   error Δx = [Δρ; Δρ̇; Δσ; Δω; Δb]
//
// Δσ is the body-frame multiplicative error, R(σ) = R(Δσ) R(σ̂); the other errors are
// additive. The model types follow runtime/ekf.hpp's requirements plus the manifold hooks
// boxplus (the correction x ⊞ Δx, (194)) and normalise (the shadow-set switch, (195)).
// Both classes read the frames of the current epoch (GpsInsEpoch), which the caller sets
// before each step. Needs Eigen only.
#pragma once
#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <stdexcept>

#include "hinf/models/attitude.hpp"

namespace hinf::models {

constexpr int kGpsInsSatellites = 4;
constexpr int kGpsInsBaselines = 3;
constexpr double kSpeedOfLight = 299792458.0;  // m/s

// Offsets of the blocks of x and Δx.
namespace gps_ins_index {
constexpr int kPosition = 0, kVelocity = 3, kAttitude = 6, kRate = 9, kBias = 12;
}

// `full`: the Jacobians of the model (docs/maths.md (190), (193)); `paper`: the printed ones,
// which drop −[(Ω+ν)×] in F_ω, the Δσ coupling of ω̇ and the gyro's 4[(Ω+ν)×] (§29.4).
enum class GpsInsJacobian { Full, Paper };

// `exact`: the CW translation by its transition matrix, (σ, ω) by one RK4 step with the frames
// turning inside it, Φ = I + FΔt + (FΔt)²/2 + (FΔt)³/6 (docs/maths.md (188a)); `euler`: the
// source's Euler step (188) and Φ = I + FΔt (191).
enum class GpsInsPropagation { Exact, Euler };

// The known geometry at the epoch t_k (docs/maths.md §29.2).
struct GpsInsEpoch {
  Eigen::Matrix3d R_FR = Eigen::Matrix3d::Identity();  // fly-around frame F from LVLH R
  Eigen::Matrix3d R_RI = Eigen::Matrix3d::Identity();  // LVLH R from inertial I
  Eigen::Vector3d r_target = Eigen::Vector3d::Zero();   // target position in I, m
  std::array<Eigen::Vector3d, kGpsInsSatellites> r_satellite{};  // satellites in I, m
};

struct GpsInsParameters {
  double orbit_rate = 0;       // n, rad/s (rate of R relative to I, about z_R)
  double flyaround_rate = 0;   // n_f, rad/s (rate of F relative to R, about z_F)
  double sample_time = 1;      // Δt, s
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();  // J_nom, kg m² (symmetric PD)
  double carrier_frequency = 1575.42e6;                    // Hz (GPS L1)
  // b12 = a2 − a1, b13 = a3 − a1, b23 = a3 − a2 in B, m
  std::array<Eigen::Vector3d, kGpsInsBaselines> baselines{};
  GpsInsJacobian jacobian = GpsInsJacobian::Full;
  GpsInsPropagation propagation = GpsInsPropagation::Exact;

  // Throws std::invalid_argument naming the field.
  void validate() const {
    if (!std::isfinite(orbit_rate) || !std::isfinite(flyaround_rate))
      throw std::invalid_argument("orbit_rate, flyaround_rate: must be finite");
    if (!(sample_time > 0) || !std::isfinite(sample_time)) throw std::invalid_argument("sample_time: must be > 0");
    if (!(carrier_frequency > 0) || !std::isfinite(carrier_frequency))
      throw std::invalid_argument("carrier_frequency: must be > 0");
    if (!inertia.allFinite() || (inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-12 * inertia.norm() ||
        Eigen::LLT<Eigen::Matrix3d>(inertia).info() != Eigen::Success)
      throw std::invalid_argument("inertia: must be symmetric positive definite");
    for (const auto& b : baselines)
      if (!b.allFinite()) throw std::invalid_argument("baselines: must be finite");
  }
};

// The frame rates of a state (docs/maths.md (187)): Ω = R(σ)[0,0,n_f]ᵀ (F relative to R),
// ν = R(σ) R_FR [0,0,n]ᵀ (R relative to I), ω_BI = ω + Ω + ν, all in B.
struct GpsInsRates {
  Eigen::Vector3d Omega, nu, omega_BI;
};

inline GpsInsRates gps_ins_rates(const GpsInsParameters& p, const Eigen::Matrix3d& R_FR,
                                 const Eigen::Vector3d& sigma,
                                 const Eigen::Vector3d& omega) {
  const Eigen::Matrix3d R_BF = mrp_to_dcm(sigma);
  GpsInsRates r;
  r.Omega = R_BF * Eigen::Vector3d(0, 0, p.flyaround_rate);
  r.nu = R_BF * (R_FR * Eigen::Vector3d(0, 0, p.orbit_rate));
  r.omega_BI = omega + r.Omega + r.nu;
  return r;
}

// x ⊞ Δx (docs/maths.md (194)): additive, and σ ← Δσ ⊗ σ (R(σ) ← R(Δσ) R(σ)).
template <class Vec>
Vec gps_ins_boxplus(const Vec& x, const Vec& dx) {
  using namespace gps_ins_index;
  Vec out = x + dx;
  out.template segment<3>(kAttitude) = mrp_compose(dx.template segment<3>(kAttitude), x.template segment<3>(kAttitude));
  return out;
}

// x_a ⊟ x_b: additive, and Δσ with R(Δσ) = R(σ_a) R(σ_b)ᵀ, short set (the inverse of ⊞).
template <class Vec>
Vec gps_ins_boxminus(const Vec& xa, const Vec& xb) {
  using namespace gps_ins_index;
  Vec out = xa - xb;
  out.template segment<3>(kAttitude) =
      mrp_canonical(mrp_compose(xa.template segment<3>(kAttitude), -xb.template segment<3>(kAttitude)));
  return out;
}

class GpsInsProcess {
 public:
  static constexpr int NX = 15;
  static constexpr int NU = 3;  // the control torque T_c (N m), known to the filter
  using State = Eigen::Matrix<double, 15, 1>;
  using Input = Eigen::Vector3d;
  using Jacobian = Eigen::Matrix<double, 15, 15>;

  explicit GpsInsProcess(const GpsInsParameters& p) : p_(p) {
    p_.validate();
    J_inv_ = p_.inertia.inverse();
    // exp(F_ρ Δt) by its Taylor series (‖F_ρ Δt‖ ≪ 1: n Δt ≈ 1e-3 in the fly-around)
    const Eigen::Matrix<double, 6, 6> A = p_.sample_time * translation_matrix();
    Eigen::Matrix<double, 6, 6> term = Eigen::Matrix<double, 6, 6>::Identity();
    translation_transition_ = term;
    for (int k = 1; k <= 30 && term.norm() > 0; ++k) {
      term = term * A / k;
      translation_transition_ += term;
    }
  }

  void set_epoch(const GpsInsEpoch& e) { epoch_ = e; }
  const GpsInsEpoch& epoch() const { return epoch_; }
  const GpsInsParameters& parameters() const { return p_; }

  // ω̇ of the model, docs/maths.md (189):
  //   ω̇ = J⁻¹[T_c − ω_BI × J ω_BI] − (Ω + ν) × ω + Ω × ν
  Eigen::Vector3d rate_derivative(const State& x, const Input& T_c) const {
    return rate_derivative(x.segment<3>(gps_ins_index::kAttitude), x.segment<3>(gps_ins_index::kRate), T_c,
                           epoch_.R_FR);
  }

  // One step of Δt, docs/maths.md (188)–(189), (188a); b constant.
  State f(const State& x, const Input& T_c) const {
    using namespace gps_ins_index;
    const double dt = p_.sample_time;
    State out = x;
    const Eigen::Vector3d s = x.segment<3>(kAttitude), w = x.segment<3>(kRate);
    if (p_.propagation == GpsInsPropagation::Euler) {
      out.head<6>() += dt * (translation_matrix() * x.head<6>());
      out.segment<3>(kAttitude) += dt * (mrp_kinematics(s) * w);
      out.segment<3>(kRate) += dt * rate_derivative(s, w, T_c, epoch_.R_FR);
      return out;
    }
    out.head<6>() = translation_transition_ * x.head<6>();
    // RK4 of (183), (189) with R_FR(t + τ) = R3(n_f τ) R_FR(t)
    const Eigen::Matrix3d R_half = rotation_3(p_.flyaround_rate * dt / 2) * epoch_.R_FR;
    const Eigen::Matrix3d R_end = rotation_3(p_.flyaround_rate * dt) * epoch_.R_FR;
    const Eigen::Vector3d s1 = mrp_kinematics(s) * w, w1 = rate_derivative(s, w, T_c, epoch_.R_FR);
    const Eigen::Vector3d sa = s + dt / 2 * s1, wa = w + dt / 2 * w1;
    const Eigen::Vector3d s2 = mrp_kinematics(sa) * wa, w2 = rate_derivative(sa, wa, T_c, R_half);
    const Eigen::Vector3d sb = s + dt / 2 * s2, wb = w + dt / 2 * w2;
    const Eigen::Vector3d s3 = mrp_kinematics(sb) * wb, w3 = rate_derivative(sb, wb, T_c, R_half);
    const Eigen::Vector3d sc = s + dt * s3, wc = w + dt * w3;
    const Eigen::Vector3d s4 = mrp_kinematics(sc) * wc, w4 = rate_derivative(sc, wc, T_c, R_end);
    out.segment<3>(kAttitude) = s + dt / 6 * (s1 + 2 * s2 + 2 * s3 + s4);
    out.segment<3>(kRate) = w + dt / 6 * (w1 + 2 * w2 + 2 * w3 + w4);
    return out;
  }

  // Φ = I + F Δt (191), or with the (FΔt)²/2 + (FΔt)³/6 terms for `exact` (188a).
  Jacobian F(const State& x, const Input& /*T_c*/) const {
    const Jacobian A = p_.sample_time * continuous_jacobian(x);
    Jacobian Phi = Jacobian::Identity() + A;
    if (p_.propagation == GpsInsPropagation::Exact) {
      const Jacobian A2 = A * A;
      Phi += 0.5 * A2;
      Phi.noalias() += A2 * A / 6;
    }
    return Phi;
  }

  // F of the error dynamics, docs/maths.md (190) (`paper`: (192)).
  Jacobian continuous_jacobian(const State& x) const {
    using namespace gps_ins_index;
    const Eigen::Vector3d w = x.segment<3>(kRate);
    const GpsInsRates r = gps_ins_rates(p_, epoch_.R_FR, x.segment<3>(kAttitude), w);
    const Eigen::Matrix3d& J = p_.inertia;
    const Eigen::Matrix3d F_J = J_inv_ * (-cross_matrix(r.omega_BI) * J + cross_matrix(J * r.omega_BI));
    const Eigen::Matrix3d a_x = cross_matrix(r.Omega + r.nu);
    Jacobian Fc = Jacobian::Zero();
    Fc.topLeftCorner<6, 6>() = translation_matrix();
    Fc.block<3, 3>(kAttitude, kAttitude) = -cross_matrix(w);
    Fc.block<3, 3>(kAttitude, kRate) = 0.25 * Eigen::Matrix3d::Identity();
    if (p_.jacobian == GpsInsJacobian::Paper) {
      Fc.block<3, 3>(kRate, kRate) = F_J;
      return Fc;
    }
    Fc.block<3, 3>(kRate, kRate) = F_J - a_x;
    Fc.block<3, 3>(kRate, kAttitude) = 4 * (F_J + cross_matrix(w)) * a_x -
                                       4 * cross_matrix(r.nu) * cross_matrix(r.Omega) +
                                       4 * cross_matrix(r.Omega) * cross_matrix(r.nu);
    return Fc;
  }

  // The CW matrix F_ρ = A₁(n) of docs/maths.md (63), (188).
  Eigen::Matrix<double, 6, 6> translation_matrix() const {
    const double n = p_.orbit_rate;
    Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
    A.topRightCorner<3, 3>().setIdentity();
    A(3, 0) = 3 * n * n;
    A(3, 4) = 2 * n;
    A(4, 3) = -2 * n;
    A(5, 2) = -n * n;
    return A;
  }

  const Eigen::Matrix<double, 6, 6>& translation_transition() const { return translation_transition_; }

  // The manifold hooks of runtime/ekf.hpp.
  State boxplus(const State& x, const State& dx) const { return gps_ins_boxplus(x, dx); }
  // The shadow-set switch (195). R(σ) is unchanged, so the body-frame error Δσ is too: its
  // Jacobian is the identity and P is left as it is (docs/maths.md §29.6).
  void normalise(State& x, Jacobian& /*P*/) const {
    x.segment<3>(gps_ins_index::kAttitude) = mrp_canonical(x.segment<3>(gps_ins_index::kAttitude));
  }

 private:
  Eigen::Vector3d rate_derivative(const Eigen::Vector3d& sigma, const Eigen::Vector3d& w, const Input& T_c,
                                  const Eigen::Matrix3d& R_FR) const {
    const GpsInsRates r = gps_ins_rates(p_, R_FR, sigma, w);
    return J_inv_ * (T_c - r.omega_BI.cross(p_.inertia * r.omega_BI)) - (r.Omega + r.nu).cross(w) +
           r.Omega.cross(r.nu);
  }

  GpsInsParameters p_;
  Eigen::Matrix3d J_inv_;
  Eigen::Matrix<double, 6, 6> translation_transition_;
  GpsInsEpoch epoch_;
};

// z = [gyro (3, rad/s); pseudorange single differences (4, m); carrier-phase differences
// between antennas (3 baselines × 4 satellites, baseline-major, cycles)], docs/maths.md (193).
class GpsInsMeasurement {
 public:
  static constexpr int NX = 15;
  static constexpr int NZ = 3 + kGpsInsSatellites + kGpsInsBaselines * kGpsInsSatellites;
  static constexpr int kPseudorangeRow = 3;
  static constexpr int kPhaseRow = 3 + kGpsInsSatellites;
  using State = Eigen::Matrix<double, 15, 1>;
  using Vector = Eigen::Matrix<double, NZ, 1>;
  using Jacobian = Eigen::Matrix<double, NZ, 15>;

  explicit GpsInsMeasurement(const GpsInsParameters& p) : p_(p) { p_.validate(); }

  void set_epoch(const GpsInsEpoch& e) { epoch_ = e; }
  const GpsInsEpoch& epoch() const { return epoch_; }

  double cycles_per_metre() const { return p_.carrier_frequency / kSpeedOfLight; }

  Vector h(const State& x) const {
    using namespace gps_ins_index;
    const GpsInsRates r = gps_ins_rates(p_, epoch_.R_FR, x.segment<3>(kAttitude), x.segment<3>(kRate));
    const Eigen::Vector3d r_chaser = chaser_position(x);
    const Eigen::Matrix3d R_BI = body_from_inertial(x);
    Vector z;
    z.head<3>() = r.omega_BI + x.segment<3>(kBias);
    for (int j = 0; j < kGpsInsSatellites; ++j) {
      const Eigen::Vector3d& g = epoch_.r_satellite[j];
      z(kPseudorangeRow + j) = (r_chaser - g).norm() - (epoch_.r_target - g).norm();
      const Eigen::Vector3d e_B = R_BI * (g - r_chaser).normalized();
      for (int k = 0; k < kGpsInsBaselines; ++k)
        z(kPhaseRow + k * kGpsInsSatellites + j) = cycles_per_metre() * p_.baselines[k].dot(e_B);
    }
    return z;
  }

  // ∂z/∂Δx, docs/maths.md (193) (`paper`: without the gyro's attitude block).
  Jacobian H(const State& x) const {
    using namespace gps_ins_index;
    const GpsInsRates r = gps_ins_rates(p_, epoch_.R_FR, x.segment<3>(kAttitude), x.segment<3>(kRate));
    const Eigen::Vector3d r_chaser = chaser_position(x);
    const Eigen::Matrix3d R_BI = body_from_inertial(x);
    const Eigen::Matrix3d R_IR = epoch_.R_RI.transpose();
    const double fc = cycles_per_metre();
    Jacobian Hx = Jacobian::Zero();
    if (p_.jacobian == GpsInsJacobian::Full) Hx.block<3, 3>(0, kAttitude) = 4 * cross_matrix(r.Omega + r.nu);
    Hx.block<3, 3>(0, kRate).setIdentity();
    Hx.block<3, 3>(0, kBias).setIdentity();
    for (int j = 0; j < kGpsInsSatellites; ++j) {
      const Eigen::Vector3d d = epoch_.r_satellite[j] - r_chaser;
      const double range = d.norm();
      const Eigen::Vector3d e = d / range;
      Hx.block<1, 3>(kPseudorangeRow + j, kPosition) = -e.transpose() * R_IR;
      const Eigen::Matrix3d los_position = -(Eigen::Matrix3d::Identity() - e * e.transpose()) * R_IR / range;
      const Eigen::Matrix3d e_B_x = cross_matrix(R_BI * e);
      for (int k = 0; k < kGpsInsBaselines; ++k) {
        const int row = kPhaseRow + k * kGpsInsSatellites + j;
        const Eigen::RowVector3d b = p_.baselines[k].transpose();
        Hx.block<1, 3>(row, kPosition) = fc * b * R_BI * los_position;
        Hx.block<1, 3>(row, kAttitude) = 4 * fc * b * e_B_x;
      }
    }
    return Hx;
  }

  Vector residual(const Vector& y, const Vector& y_pred) const { return y - y_pred; }

  // r_s = r_c + R_IR ρ and R_BI = R(σ) R_FR R_RI.
  Eigen::Vector3d chaser_position(const State& x) const {
    return epoch_.r_target + epoch_.R_RI.transpose() * x.head<3>();
  }
  Eigen::Matrix3d body_from_inertial(const State& x) const {
    return mrp_to_dcm(x.segment<3>(gps_ins_index::kAttitude)) * epoch_.R_FR * epoch_.R_RI;
  }

 private:
  GpsInsParameters p_;
  GpsInsEpoch epoch_;
};

// The carrier phase as double differences, docs/maths.md (193a): z_DD = D z with D the
// 16 × 19 map that keeps the gyro and pseudorange rows and replaces each baseline's four phase
// rows by the three differences against satellite 0 (a line bias common to the satellites
// cancels). h, H and R are the single-difference model's through D; independent rows of R
// become correlated ones, D R Dᵀ.
class GpsInsDoubleDifferenceMeasurement {
 public:
  static constexpr int NX = 15;
  static constexpr int NZ = 3 + kGpsInsSatellites + kGpsInsBaselines * (kGpsInsSatellites - 1);
  using State = GpsInsMeasurement::State;
  using Vector = Eigen::Matrix<double, NZ, 1>;
  using Jacobian = Eigen::Matrix<double, NZ, 15>;
  using Map = Eigen::Matrix<double, NZ, GpsInsMeasurement::NZ>;

  explicit GpsInsDoubleDifferenceMeasurement(const GpsInsParameters& p) : single_(p), D_(map()) {}

  void set_epoch(const GpsInsEpoch& e) { single_.set_epoch(e); }
  const GpsInsEpoch& epoch() const { return single_.epoch(); }

  Vector h(const State& x) const { return D_ * single_.h(x); }
  Jacobian H(const State& x) const { return D_ * single_.H(x); }
  Vector residual(const Vector& y, const Vector& y_pred) const { return y - y_pred; }

  // D of (193a).
  static Map map() {
    constexpr int kFirstPhase = 3 + kGpsInsSatellites;
    Map D = Map::Zero();
    D.leftCols<kFirstPhase>().topRows<kFirstPhase>().setIdentity();
    for (int k = 0; k < kGpsInsBaselines; ++k)
      for (int j = 1; j < kGpsInsSatellites; ++j) {
        const int row = kFirstPhase + k * (kGpsInsSatellites - 1) + (j - 1);
        D(row, GpsInsMeasurement::kPhaseRow + k * kGpsInsSatellites + j) = 1;
        D(row, GpsInsMeasurement::kPhaseRow + k * kGpsInsSatellites) = -1;
      }
    return D;
  }

 private:
  GpsInsMeasurement single_;
  Map D_;
};

// Process noise of docs/maths.md (196): Q = Δt² Γ blockdiag(σ_a² I + N_a, J⁻¹(σ_T² I + N_f)J⁻ᵀ,
// σ_b²/Δt I) Γᵀ with N_f = (p_f max J_ii |ω_BI|²)² I (the inertia uncertainty the filter
// assumes, recomputed at every step) and Γ = G (`zoh`: with Δt/2 I in the position rows and
// Δt/8 I in the attitude rows).
struct GpsInsProcessNoise {
  double accel_sigma = 0;                   // σ_a, m/s²
  double torque_sigma = 0;                  // σ_T, N m
  double bias_walk_sigma = 0;               // σ_b, rad/s^1.5
  double inertia_uncertainty_fraction = 0;  // p_f
  bool zoh = false;
};

inline Eigen::Matrix<double, 15, 15> gps_ins_process_noise(const GpsInsParameters& p, const GpsInsProcessNoise& q,
                                                           const Eigen::Vector3d& omega_BI) {
  using namespace gps_ins_index;
  const double dt = p.sample_time;
  const Eigen::Matrix3d J_inv = p.inertia.inverse();
  const double n_f = q.inertia_uncertainty_fraction * p.inertia.diagonal().maxCoeff() * omega_BI.squaredNorm();
  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 9, 9> W = Eigen::Matrix<double, 9, 9>::Zero();
  W.block<3, 3>(0, 0) = q.accel_sigma * q.accel_sigma * I3;
  W.block<3, 3>(3, 3) = J_inv * ((q.torque_sigma * q.torque_sigma + n_f * n_f) * I3) * J_inv.transpose();
  W.block<3, 3>(6, 6) = q.bias_walk_sigma * q.bias_walk_sigma / dt * I3;
  Eigen::Matrix<double, 15, 9> G = Eigen::Matrix<double, 15, 9>::Zero();
  G.block<3, 3>(kVelocity, 0) = I3;
  G.block<3, 3>(kRate, 3) = I3;
  G.block<3, 3>(kBias, 6) = I3;
  if (q.zoh) {
    G.block<3, 3>(kPosition, 0) = 0.5 * dt * I3;
    G.block<3, 3>(kAttitude, 3) = 0.125 * dt * I3;
  }
  Eigen::Matrix<double, 15, 15> Q = dt * dt * G * W * G.transpose();
  return 0.5 * (Q + Q.transpose());
}

// The REKF's uncertainty of docs/maths.md (197) ("Jacobian fraction"), with s the per-state
// scale (s = scale_factor × the initial 1σ):
//   L = diag(1/s) on the σ and ω blocks (zero on ρ, ρ̇, b),
//   A_k = κ_A Δt F_rate diag(s)  (F_rate: F's rows of the rate equation, every other row zero: the
//         CW translation, the MRP kinematics and the bias walk are exact),
//   C_k = κ_C H_k diag(s)  (NZ × 15, passed to the runtime as the square factor [C_k 0]).
using GpsInsScale = Eigen::Matrix<double, 15, 1>;
template <int NZ>
using GpsInsMeasurementUncertainty = Eigen::Matrix<double, NZ, NZ>;

inline Eigen::Matrix<double, 15, 15> gps_ins_rekf_A(const Eigen::Matrix<double, 15, 15>& F_continuous,
                                                    const GpsInsScale& scale, double dt, double kappa_A) {
  Eigen::Matrix<double, 15, 15> F_rate = Eigen::Matrix<double, 15, 15>::Zero();
  F_rate.middleRows<3>(gps_ins_index::kRate) = F_continuous.middleRows<3>(gps_ins_index::kRate);
  return kappa_A * dt * F_rate * scale.asDiagonal();
}

template <int NZ>
GpsInsMeasurementUncertainty<NZ> gps_ins_rekf_C(const Eigen::Matrix<double, NZ, 15>& H, const GpsInsScale& scale,
                                                double kappa_C) {
  static_assert(NZ >= 15, "the square factor [C_k 0] needs NZ >= 15");
  GpsInsMeasurementUncertainty<NZ> C = GpsInsMeasurementUncertainty<NZ>::Zero();
  C.template leftCols<15>() = kappa_C * H * scale.asDiagonal();
  return C;
}

// L only on Δσ and Δω: F_rate's only non-zero columns (the rate equation's error depends on the
// attitude and the rate, not on ρ, ρ̇ or b; an L on the slowly observed b, or on the
// unobservable split of ω and b, made γ²I − LPLᵀ fail at almost every step, §29.7).
inline Eigen::Matrix<double, 15, 15> gps_ins_rekf_L(const GpsInsScale& scale) {
  Eigen::Matrix<double, 15, 15> L = Eigen::Matrix<double, 15, 15>::Zero();
  for (int i = gps_ins_index::kAttitude; i < gps_ins_index::kBias; ++i) L(i, i) = 1 / scale(i);
  return L;
}

struct GpsInsRekfUncertainty {
  Eigen::Matrix<double, 15, 15> A, L;
  GpsInsMeasurementUncertainty<GpsInsMeasurement::NZ> C;
};

inline GpsInsRekfUncertainty gps_ins_rekf_uncertainty(const Eigen::Matrix<double, 15, 15>& F_continuous,
                                                      const GpsInsMeasurement::Jacobian& H, const GpsInsScale& scale,
                                                      double dt, double kappa_A, double kappa_C) {
  return {gps_ins_rekf_A(F_continuous, scale, dt, kappa_A), gps_ins_rekf_L(scale), gps_ins_rekf_C(H, scale, kappa_C)};
}

}  // namespace hinf::models
