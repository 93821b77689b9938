// The worst case of a fixed filter over the admissible uncertainty, found (not bounded):
// `hinf-synth analyze`'s answer to "how bad can it get", beside the certified γ that
// bounds it from above (docs/maths.md §24).
#pragma once
#include <Eigen/Dense>
#include <vector>

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


// The same over a box of scalars: F = diag(δ₁ I_{s₁}, …, δ_K I_{s_K}) (Σ s_b = j = k) with
// lower_b ≤ δ_b ≤ upper_b inside [−1, 1] — named parameters' own box (docs/maths.md §22, §24),
// a subset of the admissible F. Found by the box's centre and vertices (all of them up to
// kMaxBoxVertexDimension scalars), a Halton sample of `samples` points, and a compass search
// from the best (each scalar moved by ± a step of its width, the step halved when no move
// gains). +inf (with that δ) if some δ makes the error system unstable.
inline constexpr int kMaxBoxVertexDimension = 10;
struct WorstCaseOverBox {
  double gain = 0;        // σ_max at the peak frequency for δ (a lower value of ‖·‖∞ there)
  Eigen::VectorXd delta;  // K: the worst scalars found
  int evaluations = 0;    // H∞ norms computed
};
WorstCaseOverBox worst_case_gain_over_box(const Plant& plant, const Filter& filter, const std::vector<int>& sizes,
                                          const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, int samples);

}  // namespace hinf::certify
