// Parse a hand-written gains file through the installed hinf::runtime_yaml and run one
// step (same scalar filter as consumer_lti.cpp: expected outputs 4 and 8).
#include <hinf/runtime/lti_filter.hpp>
#include <hinf/runtime_yaml/gains_file.hpp>

#include <cmath>
#include <cstdio>
#include <exception>

int main() {
  try {
    const char* text =
        "format: hinf-gains/1\n"
        "filter:\n"
        "  A_F: [[0.5]]\n"
        "  B_F: [[1.0]]\n"
        "  C_F: [[2.0]]\n";
    const auto g = hinf::runtime_yaml::parse_gains_yaml(text, "<consumer>");
    hinf::runtime::LtiFilter f(g.A_F, g.B_F, g.C_F);
    Eigen::VectorXd z0(1), y(1);
    z0 << 4.0;
    y << 3.0;
    f.init(z0);
    const double a = f.step(y)(0), b = f.step(y)(0);
    std::printf("yaml: z_F(0) = %.17g, z_F(1) = %.17g\n", a, b);
    return (std::abs(a - 4.0) < 1e-14 && std::abs(b - 8.0) < 1e-14) ? 0 : 1;
  } catch (const std::exception& e) {
    std::printf("FAIL: %s\n", e.what());
    return 1;
  }
}
