// Standard normal deviates that are the same on every platform (check 2's random F and the
// worst-case search of certify/worst_case.hpp).
#pragma once
#include <cmath>
#include <random>

namespace hinf::certify::detail {

// Standard normal deviates by the Box–Muller transform from raw mt19937_64 output
// (std::normal_distribution is implementation-defined; this is not).
class GaussianSource {
 public:
  explicit GaussianSource(unsigned seed) : engine_(seed) {}
  double next() {
    if (has_spare_) { has_spare_ = false; return spare_; }
    // 53-bit uniforms in (0, 1].
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double t = 2.0 * 3.14159265358979323846 * u2;
    spare_ = r * std::sin(t);
    has_spare_ = true;
    return r * std::cos(t);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace hinf::certify::detail
