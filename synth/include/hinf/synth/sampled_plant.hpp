// A continuous-time plant given in a config's `system:` with `sample_time` (docs/maths.md §19):
//   ẋ = (A + H F E) x + G u + B w,  y = C x + D v,  z = L x,
// sampled into the discrete plant of docs/maths.md (1)–(4), (120) that every synthesis takes.
#pragma once
#include "hinf/models/discretise.hpp"
#include "hinf/models/plant.hpp"

namespace hinf::synth {

struct SamplingSpec {
  double sample_time = 0;  // T, s (> 0)
  models::Discretisation method = models::Discretisation::ZeroOrderHold;
  // false: w held over the sample like u (B = Γ B_c); true: w is continuous white noise of
  // intensity B_c B_cᵀ, and B is a square root of its sampled covariance (Van Loan, (131))
  bool white_process_noise = false;
};

// A, B, G and H sampled by docs/maths.md (128)–(131); C, D, L kept; E kept (Euler, ZOH) or
// E (I + A)/2 (Tustin, the first-order map of (130)). Throws Error::invalid_field naming
// sample_time if the sampled matrices are not finite.
Plant sample_plant(const Plant& continuous, const SamplingSpec& spec);

}  // namespace hinf::synth
