#include "hinf/sim/two_body.hpp"

#include <cmath>

namespace hinf::sim {

RelativeTwoBody::RelativeTwoBody(double mu, double orbital_rate)
    : mu_(mu), omega_(orbital_rate), radius_(std::cbrt(mu / (orbital_rate * orbital_rate))) {}

Vector6 RelativeTwoBody::derivative(const Vector6& s, const Vector3& a) const {
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

Vector6 RelativeTwoBody::propagate(const Vector6& state, const Vector3& accel, double dt,
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

}  // namespace hinf::sim
