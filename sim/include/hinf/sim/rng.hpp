// Seeded random numbers for the simulations: a fixed engine (std::mt19937_64, whose
// output sequence the C++ standard specifies) and distributions written out here, so
// that the same seed gives the same numbers with any standard library and any number
// of threads. std::normal_distribution & co. are implementation-defined; not used.
#pragma once
#include <cmath>
#include <cstdint>
#include <random>

namespace hinf::sim {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mixer.
inline std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Seed of an independent stream identified by (parent seed, index). Used for the
// per-run seed (seed, run index) and for the per-channel streams inside a run.
inline std::uint64_t derive_seed(std::uint64_t parent, std::uint64_t index) {
  return splitmix64(splitmix64(parent) ^ splitmix64(index + 0x632BE59BD9B4E019ULL));
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  // Uniform on [0, 1) with 53 random bits.
  double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Uniform on (0, 1].
  double uniform01_open_low() { return 1.0 - uniform01(); }
  // Standard normal (Box–Muller, the second value cached).
  double normal() {
    if (has_cached_) {
      has_cached_ = false;
      return cached_;
    }
    const double u1 = uniform01_open_low();
    const double u2 = uniform01();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * M_PI * u2;
    cached_ = radius * std::sin(angle);
    has_cached_ = true;
    return radius * std::cos(angle);
  }
  // Gamma(shape, 1) by Marsaglia & Tsang (2000); shape < 1 via the boost u^{1/shape}.
  double gamma(double shape) {
    if (shape < 1.0) return gamma(shape + 1.0) * std::pow(uniform01_open_low(), 1.0 / shape);
    const double d = shape - 1.0 / 3.0;
    const double c = 1.0 / std::sqrt(9.0 * d);
    for (;;) {
      double x, v;
      do {
        x = normal();
        v = 1.0 + c * x;
      } while (v <= 0.0);
      v = v * v * v;
      const double u = uniform01_open_low();
      if (std::log(u) < 0.5 * x * x + d - d * v + d * std::log(v)) return d * v;
    }
  }
  // Student-t with nu degrees of freedom (unit scale): N / sqrt(chi²_nu / nu).
  double student_t(double nu) {
    const double z = normal();
    const double chi2 = 2.0 * gamma(0.5 * nu);
    return z / std::sqrt(chi2 / nu);
  }

 private:
  std::mt19937_64 engine_;
  double cached_ = 0.0;
  bool has_cached_ = false;
};

}  // namespace hinf::sim
