// The largest singular value of a discrete-time system's frequency response on a grid of
// frequencies: the σ(θ) curve `hinf-synth compare` draws (docs/maths.md §25). The H∞ norm
// itself comes from hinf_norm.hpp, never from a grid.
#pragma once
#include <vector>

#include "hinf/models/state_space.hpp"

namespace hinf::certify {

// θ (rad/sample): `points` ≥ 2 values log-spaced over [π·10⁻⁴, π], merged with `extra`
// (each in [0, π]; a peak frequency, say), sorted, duplicates removed.
std::vector<double> frequency_grid(int points, const std::vector<double>& extra);

// σ_max(G(e^{jθ})) for each θ (+inf where e^{jθ} is numerically an eigenvalue of A).
std::vector<double> sigma_max_on_grid(const hinf::StateSpace& system, const std::vector<double>& theta);

}  // namespace hinf::certify
