// The worst case of a fixed filter over the admissible uncertainty, found (not bounded):
// `hinf-synth analyze`'s answer to "how bad can it get", beside the certified γ that
// bounds it from above (docs/maths.md §24).
#pragma once
#include <Eigen/Dense>

#include "hinf/models/plant.hpp"

namespace hinf::certify {

// The largest H∞ norm of the error system (11) at a constant admissible F found by
// sampling (admissible_samples) and a seeded local search from the worst sample (random
// perturbations kept inside the admissible set, step halved after each miss): a lower
// bound on the worst-case ℓ₂ gain over every admissible F(k) — the certified γ is the upper
// one (docs/maths.md §24). +inf (with that F) if some sampled F makes it unstable.
struct WorstCaseGain {
  double gain = 0;          // σ_max at the peak frequency for worst_F (a lower value of ‖·‖∞)
  Eigen::MatrixXd worst_F;  // j×k (empty: the nominal plant was the worst)
  int evaluations = 0;      // H∞ norms computed
};
WorstCaseGain worst_case_gain(const Plant& plant, const Filter& filter, int random_samples, unsigned seed);

}  // namespace hinf::certify
