// Noise models for the simulations (process acceleration and ρ, α, β measurement noise).
// A channel is the sum of its components; every random component has its own seeded
// stream. Random components are parameterised by their standard deviation `sigma`, so
// that different shapes with the same sigma have the same variance.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "hinf/sim/rng.hpp"

namespace hinf::sim {

enum class NoiseKind {
  Gaussian,      // N(0, σ²)
  GaussMarkov,   // first-order Gauss–Markov: n(k+1) = φ n(k) + σ√(1−φ²) w(k), φ = e^{−T/τ}; n(0) ~ N(0, σ²)
  Uniform,       // U(−σ√3, σ√3)
  Laplace,       // Laplace with scale σ/√2
  StudentT,      // Student-t with ν > 2 degrees of freedom, scaled to standard deviation σ
  Impulsive,     // with probability p per sample: ±magnitude (random sign), else 0
  Sinusoid,      // deterministic a·sin(2π f (t − t₀) + φ) on [t₀, t₁), a set by the ℓ₂ energy
  Pulse          // deterministic constant a on [t₀, t₁), a set by the ℓ₂ energy
};

const char* noise_kind_name(NoiseKind kind);

struct NoiseComponent {
  NoiseKind kind = NoiseKind::Gaussian;
  double sigma = 0.0;          // Gaussian, GaussMarkov, Uniform, Laplace, StudentT
  double time_constant = 0.0;  // GaussMarkov τ, s
  double dof = 0.0;            // StudentT ν
  double probability = 0.0;    // Impulsive p
  double magnitude = 0.0;      // Impulsive
  double energy = 0.0;         // Sinusoid, Pulse: Σ_k d(k)² over the samples of the window
  double frequency_hz = 0.0;   // Sinusoid
  double phase = 0.0;          // Sinusoid, rad
  double start = 0.0;          // Sinusoid, Pulse: window start, s
  double end = -1.0;           // Sinusoid, Pulse: window end, s (< 0: end of the run)
};

// Variance per sample of the random part of a channel (for the EKF's Q and R).
// Deterministic energy-bounded components contribute nothing: they are not random.
double channel_variance(const std::vector<NoiseComponent>& components);

// One noise channel, sampled at t_k = k·T, k = 0 … steps−1.
class NoiseChannel {
 public:
  NoiseChannel(std::vector<NoiseComponent> components, double sample_time, long steps,
               std::uint64_t seed);
  // The value at sample k; must be called for k = 0, 1, 2, … in order.
  double next();

 private:
  struct State {
    NoiseComponent spec;
    Rng rng;
    double markov = 0.0;     // Gauss–Markov state
    double amplitude = 0.0;  // deterministic components
    long first = 0, last = 0;  // deterministic window: samples [first, last)
  };
  std::vector<State> states_;
  double sample_time_;
  long k_ = 0;
};

}  // namespace hinf::sim
