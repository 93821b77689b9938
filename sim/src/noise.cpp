#include "hinf/sim/noise.hpp"

#include <cmath>
#include <stdexcept>

namespace hinf::sim {

const char* noise_kind_name(NoiseKind kind) {
  switch (kind) {
    case NoiseKind::Gaussian: return "gaussian";
    case NoiseKind::GaussMarkov: return "gauss_markov";
    case NoiseKind::Uniform: return "uniform";
    case NoiseKind::Laplace: return "laplace";
    case NoiseKind::StudentT: return "student_t";
    case NoiseKind::Impulsive: return "impulsive";
    case NoiseKind::Sinusoid: return "sinusoid";
    case NoiseKind::Pulse: return "pulse";
  }
  return "?";
}

double channel_variance(const std::vector<NoiseComponent>& components) {
  double variance = 0.0;
  for (const auto& c : components) {
    switch (c.kind) {
      case NoiseKind::Gaussian:
      case NoiseKind::GaussMarkov:
      case NoiseKind::Uniform:
      case NoiseKind::Laplace:
      case NoiseKind::StudentT: variance += c.sigma * c.sigma; break;
      case NoiseKind::Impulsive: variance += c.probability * c.magnitude * c.magnitude; break;
      case NoiseKind::Sinusoid:
      case NoiseKind::Pulse: break;
    }
  }
  return variance;
}

NoiseChannel::NoiseChannel(std::vector<NoiseComponent> components, double sample_time,
                           long steps, std::uint64_t seed)
    : sample_time_(sample_time) {
  for (std::size_t i = 0; i < components.size(); ++i) {
    State s{components[i], Rng(derive_seed(seed, i)), 0.0, 0.0, 0, 0};
    const auto& c = s.spec;
    if (c.kind == NoiseKind::GaussMarkov) {
      s.markov = c.sigma * s.rng.normal();  // stationary start
    }
    if (c.kind == NoiseKind::Sinusoid || c.kind == NoiseKind::Pulse) {
      // Window [start, end) in samples: k with start ≤ k·T < end.
      const double end = c.end < 0.0 ? steps * sample_time : c.end;
      s.first = static_cast<long>(std::ceil(c.start / sample_time - 1e-9));
      s.last = static_cast<long>(std::ceil(end / sample_time - 1e-9));
      if (s.first < 0) s.first = 0;
      if (s.last > steps) s.last = steps;
      double shape_energy = 0.0;  // Σ shape(k)² over the window, unit amplitude
      for (long k = s.first; k < s.last; ++k) {
        const double v = c.kind == NoiseKind::Pulse
                             ? 1.0
                             : std::sin(2.0 * M_PI * c.frequency_hz * (k * sample_time - c.start) + c.phase);
        shape_energy += v * v;
      }
      s.amplitude = shape_energy > 0.0 ? std::sqrt(c.energy / shape_energy) : 0.0;
    }
    states_.push_back(std::move(s));
  }
}

double NoiseChannel::next() {
  const long k = k_++;
  double value = 0.0;
  for (auto& s : states_) {
    const auto& c = s.spec;
    switch (c.kind) {
      case NoiseKind::Gaussian: value += c.sigma * s.rng.normal(); break;
      case NoiseKind::GaussMarkov: {
        value += s.markov;
        const double phi = std::exp(-sample_time_ / c.time_constant);
        s.markov = phi * s.markov + c.sigma * std::sqrt(1.0 - phi * phi) * s.rng.normal();
        break;
      }
      case NoiseKind::Uniform:
        value += c.sigma * std::sqrt(3.0) * (2.0 * s.rng.uniform01() - 1.0);
        break;
      case NoiseKind::Laplace: {
        // Inverse CDF with u uniform on (−1/2, 1/2): −b·sgn(u)·ln(1 − 2|u|), b = σ/√2.
        const double u = s.rng.uniform01() - 0.5;
        const double b = c.sigma / std::sqrt(2.0);
        const double mag = -b * std::log(1.0 - 2.0 * std::fabs(u));
        value += u < 0 ? -mag : mag;
        break;
      }
      case NoiseKind::StudentT:
        value += c.sigma * std::sqrt((c.dof - 2.0) / c.dof) * s.rng.student_t(c.dof);
        break;
      case NoiseKind::Impulsive: {
        const double u = s.rng.uniform01();
        const double sign = s.rng.uniform01() < 0.5 ? -1.0 : 1.0;
        if (u < c.probability) value += sign * c.magnitude;
        break;
      }
      case NoiseKind::Sinusoid:
        if (k >= s.first && k < s.last)
          value += s.amplitude *
                   std::sin(2.0 * M_PI * c.frequency_hz * (k * sample_time_ - c.start) + c.phase);
        break;
      case NoiseKind::Pulse:
        if (k >= s.first && k < s.last) value += s.amplitude;
        break;
    }
  }
  return value;
}

}  // namespace hinf::sim
