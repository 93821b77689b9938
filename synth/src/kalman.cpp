// The Kalman one-step predictor as a gains file (docs/maths.md (133)): the reference the H∞
// filter is compared with — its RMS error under white noise is the least any predictor
// achieves, its worst-case gain is what the H∞ design improves on.
#include <cmath>
#include <limits>

#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/riccati_filter.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/synth/synthesis.hpp"
#include "hinf/synth/validate_plant.hpp"

namespace hinf::synth {
namespace {
// The γ written is the achieved bound rounded up by this (it must pass the certificate).
constexpr double kClaimMargin = 1e-7;
}  // namespace

SynthesisResult kalman_predictor(const Plant& plant, const Settings& settings) {
  validate_plant(plant);
  settings.validate();
  const certify::HinfPredictorLevel kf =
      certify::hinf_predictor_at_level(plant, std::numeric_limits<double>::infinity());
  if (!kf.feasible)
    throw Error(ErrorCode::Infeasible,
                "no stationary Kalman predictor: " + kf.reason +
                    " (the DARE needs (A, C) detectable and no mode on the unit circle unreached by the noise B)");
  SynthesisResult r;
  r.filter = kf.filter;
  r.solver.method = "Kalman one-step predictor: stabilising DARE solution by ordered QZ (docs/maths.md (56)-(59) at "
                    "gamma = infinity, Q = B B^T, R = D D^T)";
  const double nominal = certify::discrete_hinf_norm(certify::error_system(plant, r.filter), 1e-10).norm;
  double claim = nominal * (1 + kClaimMargin);
  if (plant.uncertain()) claim = std::max(claim, robust_bound(plant, r.filter, settings) * (1 + kClaimMargin));
  r.certificate = certify_filter(plant, r.filter, claim, settings);
  if (!r.certificate.passed)
    throw Error(ErrorCode::NumericalFailure,
                "the Kalman predictor's certificate failed at gamma = " + significant_text(claim, 10) + "; no gains written");
  r.gamma = claim;
  r.gamma_squared = claim * claim;
  r.bound = bound_statement(FilterForm::Observer, plant.uncertain());
  return r;
}

}  // namespace hinf::synth
