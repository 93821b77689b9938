#include "hinf/certify/frequency_sweep.hpp"

#include <algorithm>
#include <cmath>

#include "frequency_response.hpp"

namespace hinf::certify {
namespace {
// The grid's lowest frequency, as a fraction of π (Nyquist).
constexpr double kLowestFraction = 1e-4;
}  // namespace

std::vector<double> frequency_grid(int points, const std::vector<double>& extra) {
  std::vector<double> theta;
  const double lo = std::log(kLowestFraction * detail::kPi), hi = std::log(detail::kPi);
  for (int i = 0; i < points; ++i) theta.push_back(std::exp(lo + (hi - lo) * i / (points - 1)));
  theta.back() = detail::kPi;  // exactly Nyquist
  for (double t : extra)
    if (t >= 0 && t <= detail::kPi) theta.push_back(t);
  std::sort(theta.begin(), theta.end());
  theta.erase(std::unique(theta.begin(), theta.end()), theta.end());
  return theta;
}

std::vector<double> sigma_max_on_grid(const hinf::StateSpace& system, const std::vector<double>& theta) {
  const detail::FrequencyResponse G(system.A, system.B, system.C, system.D);
  std::vector<double> sigma;
  sigma.reserve(theta.size());
  for (double t : theta) {
    const double s = G.sigma_max(t);
    sigma.push_back(std::isfinite(s) ? s : INFINITY);
  }
  return sigma;
}

}  // namespace hinf::certify
