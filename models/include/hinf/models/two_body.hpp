// Truth model of the simulator (header-only, Eigen only): exact (nonlinear) two-body
// relative motion of the chaser about a target on a circular orbit, in the target's rotating frame (docs/maths.md §9.1 frame: x radial,
// y along-track, z orbit normal). Not the Hill/CW linearisation.
//
//   ẍ =  2ωẏ + ω²(R+x) − μ(R+x)/r³ + a_x
//   ÿ = −2ωẋ + ω² y    − μ y/r³     + a_y
//   z̈ =               − μ z/r³     + a_z,       r = |(R+x, y, z)|,  ω² = μ/R³
//
// Linearised about the origin this is the Hill equation docs/maths.md (62) (ẍ = 3ω²x + 2ωẏ, …).
#pragma once
#include <Eigen/Dense>

#include <cmath>

namespace hinf::models {

constexpr double kEarthMu = 3.986004418e14;  // m³/s², docs/maths.md (86)

class RelativeTwoBody {
 public:
  using Vector3 = Eigen::Matrix<double, 3, 1>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;

  // The target's circular orbit from its rate ω: R = (μ/ω²)^{1/3}.
  RelativeTwoBody(double mu, double orbital_rate);

  double mu() const { return mu_; }
  double orbital_rate() const { return omega_; }
  double orbit_radius() const { return radius_; }

  // State derivative [ẋ ẏ ż ẍ ÿ z̈] for the state [x y z ẋ ẏ ż] and a specific force
  // (m/s²) in the rotating frame.
  Vector6 derivative(const Vector6& state, const Vector3& accel) const;

  // Classical RK4 over dt in `substeps` equal steps, accel held constant (zero-order hold).
  Vector6 propagate(const Vector6& state, const Vector3& accel, double dt, int substeps) const;

 private:
  double mu_, omega_, radius_;
};

inline RelativeTwoBody::RelativeTwoBody(double mu, double orbital_rate)
    : mu_(mu), omega_(orbital_rate), radius_(std::cbrt(mu / (orbital_rate * orbital_rate))) {}

inline RelativeTwoBody::Vector6 RelativeTwoBody::derivative(const Vector6& s, const Vector3& a) const {
  const double x = s(0), y = s(1), z = s(2);
  const double R = radius_;
  const double X = R + x;
  const double r2 = X * X + y * y + z * z;
  const double r = std::sqrt(r2);
  // ω² − μ/r³ = μ (1/R³ − 1/r³) = μ (r³ − R³)/(R³ r³), evaluated without cancellation:
  // r − R = (2Rx + x² + y² + z²)/(r + R),  r³ − R³ = (r − R)(r² + rR + R²).
  const double r_minus_R = (2.0 * R * x + x * x + y * y + z * z) / (r + R);
  const double r3 = r2 * r;
  const double R3 = R * R * R;
  const double dgrav = mu_ * r_minus_R * (r2 + r * R + R * R) / (R3 * r3);  // ω² − μ/r³
  const double w = omega_;
  Vector6 d;
  d(0) = s(3);
  d(1) = s(4);
  d(2) = s(5);
  d(3) = 2.0 * w * s(4) + X * dgrav + a(0);
  d(4) = -2.0 * w * s(3) + y * dgrav + a(1);
  d(5) = -mu_ * z / r3 + a(2);
  return d;
}

inline RelativeTwoBody::Vector6 RelativeTwoBody::propagate(const Vector6& state, const Vector3& accel, double dt,
                                   int substeps) const {
  const double h = dt / substeps;
  Vector6 s = state;
  for (int i = 0; i < substeps; ++i) {
    const Vector6 k1 = derivative(s, accel);
    const Vector6 k2 = derivative(s + 0.5 * h * k1, accel);
    const Vector6 k3 = derivative(s + 0.5 * h * k2, accel);
    const Vector6 k4 = derivative(s + h * k3, accel);
    s += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return s;
}

}  // namespace hinf::models
