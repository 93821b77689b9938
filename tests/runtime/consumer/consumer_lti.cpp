// One LtiFilter step through the installed package. Scalar filter
// A_F = 0.5, B_F = 1, C_F = 2: init(z0 = 4) gives x_F = C_F^+ z0 = 2; step(3) returns
// z_F = 2 * 2 = 4 and sets x_F = 0.5 * 2 + 3 = 4; the next step returns 8.
#include <hinf/runtime/lti_filter.hpp>

#include <cmath>
#include <cstdio>

int main() {
  Eigen::MatrixXd A(1, 1), B(1, 1), C(1, 1);
  A << 0.5;
  B << 1.0;
  C << 2.0;
  hinf::runtime::LtiFilter f(A, B, C);
  Eigen::VectorXd z0(1), y(1);
  z0 << 4.0;
  y << 3.0;
  f.init(z0);
  const double z_first = f.step(y)(0);
  const double z_second = f.step(y)(0);
  std::printf("z_F(0) = %.17g, z_F(1) = %.17g\n", z_first, z_second);
  if (std::abs(z_first - 4.0) > 1e-14 || std::abs(z_second - 8.0) > 1e-14) {
    std::printf("FAIL: expected 4 and 8\n");
    return 1;
  }
  return 0;
}
