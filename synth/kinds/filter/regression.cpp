// The check and verify policies (regression.hpp).
#include "hinf/synth/regression.hpp"

#include <algorithm>
#include <cmath>

namespace hinf::synth {

namespace {
// The tolerance at which a differing golden filter must still be certified to count as
// the same (equally optimal) result.
constexpr double kEquallyOptimalTolerance = 1e-6;
}  // namespace

GoldenComparison compare_with_golden(const SynthConfig& config, const Filter& golden_filter, double golden_gamma,
                                     const SynthesisResult& now, double rtol) {
  GoldenComparison c;
  c.gamma_relative_change = std::abs(now.gamma - golden_gamma) / std::abs(golden_gamma);
  c.filter_difference = certify::compare_filters(golden_filter, now.filter);
  c.same_gamma = c.gamma_relative_change <= rtol;
  c.same_filter = c.filter_difference.relative <= rtol;
  if (!c.same_filter) {
    // At the optimum the filter is not unique: rounding-level changes (another BLAS,
    // compiler, platform) can move the synthesised filter along a flat direction of the
    // bound. The golden filter is then still "the same" result if it is still certified,
    // for this config, at the golden γ.
    const double tol = std::min(rtol, kEquallyOptimalTolerance);
    c.golden_recertified = certify_filter(config.plant, golden_filter, golden_gamma * (1 + tol), config.settings);
    c.same_filter = c.golden_recertified->passed;
  }
  return c;
}

Verification verify_gains(const SynthConfig& config, const Filter& filter, double claimed_gamma) {
  Verification v;
  v.certificate = certify_filter(config.plant, filter, claimed_gamma, config.settings);
  v.holds = v.certificate.passed;
  if (v.holds || !v.certificate.schur_stable) return v;
  try {  // what the filter does achieve: the robust analysis LMI minimised (SDP)
    v.achieved_bound = std::max(robust_bound(config.plant, filter, config.settings), v.certificate.hinf_norm_nominal);
  } catch (const Error& e) {
    v.achieved_unknown_reason = e.what();
  }
  return v;
}

}  // namespace hinf::synth
