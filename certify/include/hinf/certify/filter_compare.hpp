// Comparison of two filters as transfer functions from y to z_F (docs/maths.md (61), [D14]): the
// result does not depend on the realization (similarity, state order, signs of states).
// For Filter f, T_f(z) = C_F (zI − A_F)⁻¹ B_F; the difference T_a − T_b is realized by
//   ([A_a 0; 0 A_b], [B_a; B_b], [C_a, −C_b], 0)
// and measured in the H∞ norm (discrete_hinf_norm).
#pragma once
#include "hinf/models/plant.hpp"

namespace hinf::certify {

struct FilterDifference {
  double hinf_norm_difference = 0;  // ‖T_a − T_b‖∞ (certified upper value)
  double relative = 0;              // hinf_norm_difference / reference_norm (0 if both 0, ∞ if only a is 0)
  double reference_norm = 0;        // ‖T_a‖∞
};

// Throws Error(InvalidInput) if a filter's dimensions are inconsistent, if the two
// filters have different numbers of inputs or outputs, or if a filter is not Schur
// stable (naming which filter and its spectral radius).
FilterDifference compare_filters(const Filter& a, const Filter& b, double rel_tol = 1e-9);

}  // namespace hinf::certify
