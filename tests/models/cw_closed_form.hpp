// The closed-form Clohessy–Wiltshire solution (x radial, y along-track, z normal, mean motion
// n, no thrust), written out from the textbook formula, not from the code under test: the
// independent reference of the Hill model's and the two-body integrator's tests.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace hinf::test {

inline Eigen::Matrix<double, 6, 1> cw_closed_form(const Eigen::Matrix<double, 6, 1>& s0, double n, double t) {
  const double c = std::cos(n * t), sn = std::sin(n * t);
  const double x0 = s0(0), y0 = s0(1), z0 = s0(2), xd = s0(3), yd = s0(4), zd = s0(5);
  Eigen::Matrix<double, 6, 1> s;
  s(0) = (4 - 3 * c) * x0 + sn / n * xd + 2 / n * (1 - c) * yd;
  s(1) = 6 * (sn - n * t) * x0 + y0 - 2 / n * (1 - c) * xd + (4 * sn - 3 * n * t) / n * yd;
  s(2) = c * z0 + sn / n * zd;
  s(3) = 3 * n * sn * x0 + c * xd + 2 * sn * yd;
  s(4) = -6 * n * (1 - c) * x0 - 2 * sn * xd + (4 * c - 3) * yd;
  s(5) = -n * sn * z0 + c * zd;
  return s;
}

}  // namespace hinf::test
