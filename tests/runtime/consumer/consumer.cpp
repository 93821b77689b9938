// External consumer of the installed hinfRuntime package (one translation unit, to keep
// the find_package test fast). Scalar filter A_F = 0.5, B_F = 1, C_F = 2:
// init(z0 = 4) gives x_F = C_F^+ z0 = 2; step(3) returns z_F = 2 * 2 = 4 and sets
// x_F = 0.5 * 2 + 3 = 4; the next step returns 8. With CONSUMER_YAML the same filter is
// also read from gains-file text through hinf::runtime_yaml.
#include <hinf/runtime/lti_filter.hpp>
#if CONSUMER_YAML
#include <hinf/runtime_yaml/gains_file.hpp>
#endif

#include <cmath>
#include <cstdio>
#include <exception>

namespace {
bool run(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C, const char* what) {
  hinf::runtime::LtiFilter f(A, B, C);
  Eigen::VectorXd z0(1), y(1);
  z0 << 4.0;
  y << 3.0;
  f.init(z0);
  const double z_first = f.step(y)(0);
  const double z_second = f.step(y)(0);
  std::printf("%s: z_F(0) = %.17g, z_F(1) = %.17g\n", what, z_first, z_second);
  return std::abs(z_first - 4.0) < 1e-14 && std::abs(z_second - 8.0) < 1e-14;
}
}  // namespace

int main() {
  try {
    Eigen::MatrixXd A(1, 1), B(1, 1), C(1, 1);
    A << 0.5;
    B << 1.0;
    C << 2.0;
    if (!run(A, B, C, "matrices")) return 1;
#if CONSUMER_YAML
    const auto g = hinf::runtime_yaml::parse_gains_yaml(
        "format: hinf-gains/1\nfilter:\n  A_F: [[0.5]]\n  B_F: [[1.0]]\n  C_F: [[2.0]]\n", "<consumer>");
    if (!run(g.A_F, g.B_F, g.C_F, "gains yaml")) return 1;
#endif
    return 0;
  } catch (const std::exception& e) {
    std::printf("FAIL: %s\n", e.what());
    return 1;
  }
}
