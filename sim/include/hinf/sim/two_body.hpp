// Truth model: exact (nonlinear) two-body relative motion of the chaser about a target
// on a circular orbit, in the target's rotating frame (docs/maths.md §9.1 frame: x radial,
// y along-track, z orbit normal). Not the Hill/CW linearisation.
//
//   ẍ =  2ωẏ + ω²(R+x) − μ(R+x)/r³ + a_x
//   ÿ = −2ωẋ + ω² y    − μ y/r³     + a_y
//   z̈ =               − μ z/r³     + a_z,       r = |(R+x, y, z)|,  ω² = μ/R³
//
// Linearised about the origin this is the Hill equation docs/maths.md (62) (ẍ = 3ω²x + 2ωẏ, …).
#pragma once
#include <Eigen/Dense>

namespace hinf::sim {

using Vector3 = Eigen::Matrix<double, 3, 1>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

constexpr double kEarthMu = 3.986004418e14;  // m³/s², docs/maths.md (86)

class RelativeTwoBody {
 public:
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

}  // namespace hinf::sim
