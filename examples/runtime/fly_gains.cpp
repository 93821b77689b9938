// Fly a certified filter from its gains file with the installed runtime (docs/runtime.md):
//   fly_gains GAINS.yaml [STEPS]     y(k) a test signal; prints z_F of the last step
#include <hinf/runtime_yaml/gains_file.hpp>
#include <hinf/runtime_yaml/lti_filter_from_gains.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) return std::fprintf(stderr, "usage: fly_gains GAINS.yaml [STEPS]\n"), 2;
  try {
    const hinf::runtime_yaml::GainsFile gains = hinf::runtime_yaml::load_gains_file(argv[1]);
    hinf::runtime::LtiFilter filter = hinf::runtime_yaml::make_lti_filter(gains, argv[1]);  // shapes, Schur stability
    filter.init(Eigen::VectorXd::Zero(filter.l()));  // x_F(0) = pinv(C_F) z0, here z0 = 0
    Eigen::VectorXd y(filter.m()), z(filter.l());
    const int steps = argc > 2 ? std::stoi(argv[2]) : 100;
    for (int k = 0; k < steps; ++k) {  // once per sample period of the design
      for (Eigen::Index i = 0; i < y.size(); ++i) y(i) = std::sin(0.01 * k * static_cast<double>(i + 1));
      z = filter.step(y);  // z_F(k) from y(0..k-1), then x_F(k+1); step() does not allocate
    }
    std::printf("%s: n = %ld, gamma = %.17g, z_F(%d) =", argv[1], static_cast<long>(filter.n()),
                gains.gamma.value_or(NAN), steps - 1);
    for (Eigen::Index i = 0; i < z.size(); ++i) std::printf(" %.17g", z(i));
    std::printf("\n");
    return 0;
  } catch (const std::exception& e) {  // hinf::Error (exit code 2 for a bad file) or std::invalid_argument
    return std::fprintf(stderr, "fly_gains: %s\n", e.what()), 2;
  }
}
