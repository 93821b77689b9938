// Noise generators: sample statistics with a seeded RNG, energy of the deterministic
// components, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hinf/sim/noise.hpp"

namespace {

using hinf::sim::NoiseChannel;
using hinf::sim::NoiseComponent;
using hinf::sim::NoiseKind;

std::vector<double> draw(const std::vector<NoiseComponent>& c, long n, std::uint64_t seed = 42, double T = 0.1) {
  NoiseChannel ch(c, T, n, seed);
  std::vector<double> v(static_cast<std::size_t>(n));
  for (auto& x : v) x = ch.next();
  return v;
}

struct Moments {
  double mean = 0, var = 0, kurt = 0;
};
Moments moments(const std::vector<double>& v) {
  Moments m;
  for (double x : v) m.mean += x;
  m.mean /= v.size();
  double m2 = 0, m4 = 0;
  for (double x : v) {
    const double d = x - m.mean;
    m2 += d * d;
    m4 += d * d * d * d;
  }
  m.var = m2 / v.size();
  m.kurt = (m4 / v.size()) / (m.var * m.var);  // 3 for a Gaussian
  return m;
}

NoiseComponent random_kind(NoiseKind k, double sigma) {
  NoiseComponent c;
  c.kind = k;
  c.sigma = sigma;
  return c;
}

constexpr long kN = 400000;

TEST(Noise, GaussianMomentsAndKurtosis) {
  const auto m = moments(draw({random_kind(NoiseKind::Gaussian, 0.5)}, kN));
  EXPECT_NEAR(m.mean, 0.0, 4 * 0.5 / std::sqrt(double(kN)));
  EXPECT_NEAR(m.var, 0.25, 0.25 * 0.01);
  EXPECT_NEAR(m.kurt, 3.0, 0.05);
}

TEST(Noise, UniformHasSigmaAndBoundedSupport) {
  const auto v = draw({random_kind(NoiseKind::Uniform, 2.0)}, kN);
  const auto m = moments(v);
  EXPECT_NEAR(m.var, 4.0, 4.0 * 0.01);
  EXPECT_NEAR(m.kurt, 1.8, 0.03);  // uniform: 9/5
  for (double x : v) ASSERT_LE(std::fabs(x), 2.0 * std::sqrt(3.0));
}

TEST(Noise, LaplaceHasSigmaAndKurtosisSix) {
  const auto m = moments(draw({random_kind(NoiseKind::Laplace, 1.0)}, kN));
  EXPECT_NEAR(m.mean, 0.0, 0.01);
  EXPECT_NEAR(m.var, 1.0, 0.02);
  EXPECT_NEAR(m.kurt, 6.0, 0.4);
}

TEST(Noise, StudentTHasSigma) {
  NoiseComponent c = random_kind(NoiseKind::StudentT, 0.3);
  c.dof = 8;  // kurtosis 3 + 6/(ν−4) = 4.5
  const auto m = moments(draw({c}, kN));
  EXPECT_NEAR(m.var, 0.09, 0.09 * 0.03);
  EXPECT_NEAR(m.kurt, 4.5, 0.5);
}

TEST(Noise, GaussMarkovVarianceAndCorrelation) {
  NoiseComponent c = random_kind(NoiseKind::GaussMarkov, 1.5);
  c.time_constant = 2.0;  // φ = exp(−0.1/2)
  const auto v = draw({c}, kN);
  const auto m = moments(v);
  const double phi = std::exp(-0.05);
  EXPECT_NEAR(m.var, 2.25, 2.25 * 0.05);  // correlated samples: fewer effective draws
  double lag1 = 0;
  for (std::size_t k = 1; k < v.size(); ++k) lag1 += (v[k] - m.mean) * (v[k - 1] - m.mean);
  lag1 /= (v.size() - 1) * m.var;
  EXPECT_NEAR(lag1, phi, 0.005);
}

TEST(Noise, ImpulsiveProbabilityAndMagnitude) {
  NoiseComponent c;
  c.kind = NoiseKind::Impulsive;
  c.probability = 0.02;
  c.magnitude = 5.0;
  const auto v = draw({c}, kN);
  long hits = 0, positive = 0;
  for (double x : v) {
    if (x != 0.0) {
      ++hits;
      ASSERT_DOUBLE_EQ(std::fabs(x), 5.0);
      positive += x > 0;
    }
  }
  const double p = double(hits) / kN;
  EXPECT_NEAR(p, 0.02, 4 * std::sqrt(0.02 * 0.98 / kN));
  EXPECT_NEAR(double(positive) / hits, 0.5, 0.03);
  EXPECT_NEAR(hinf::sim::channel_variance({c}), 0.02 * 25.0, 1e-15);
}

TEST(Noise, SinusoidAndPulseHaveTheRequestedEnergyInTheirWindow) {
  NoiseComponent s;
  s.kind = NoiseKind::Sinusoid;
  s.energy = 7.0;
  s.frequency_hz = 0.013;
  s.start = 10.0;
  s.end = 250.0;
  NoiseComponent p;
  p.kind = NoiseKind::Pulse;
  p.energy = 3.0;
  p.start = 5.0;
  p.end = 6.0;
  for (const auto& c : {s, p}) {
    const auto v = draw({c}, 5000);
    double energy = 0, outside = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double t = k * 0.1;
      if (t >= c.start - 1e-9 && t < c.end - 1e-9) energy += v[k] * v[k];
      else outside += std::fabs(v[k]);
    }
    EXPECT_NEAR(energy, c.energy, 1e-9 * c.energy);
    EXPECT_EQ(outside, 0.0);
  }
  // pulse of 1 s at T = 0.1: 10 samples of sqrt(3/10)
  const auto v = draw({p}, 100);
  EXPECT_NEAR(v[50], std::sqrt(0.3), 1e-15);
  EXPECT_EQ(v[60], 0.0);
}

TEST(Noise, SameSeedSameStreamDifferentSeedDifferentStream) {
  const std::vector<NoiseComponent> c = {random_kind(NoiseKind::Gaussian, 1.0), random_kind(NoiseKind::Laplace, 1.0)};
  EXPECT_EQ(draw(c, 1000, 7), draw(c, 1000, 7));
  EXPECT_NE(draw(c, 1000, 7), draw(c, 1000, 8));
}

TEST(Noise, SumOfComponentsAddsVariances) {
  const std::vector<NoiseComponent> c = {random_kind(NoiseKind::Gaussian, 0.3), random_kind(NoiseKind::Uniform, 0.4)};
  const auto m = moments(draw(c, kN));
  EXPECT_NEAR(m.var, 0.25, 0.25 * 0.01);
  EXPECT_NEAR(hinf::sim::channel_variance(c), 0.25, 1e-15);
}

}  // namespace
