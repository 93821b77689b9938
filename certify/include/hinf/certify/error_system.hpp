// The filtering-error system of docs/maths.md (9)–(11): with ξ = [x; x_F],
// τ = [w; v], e = z − z_F and a fixed admissible F (ΔA = H F E),
//     Ā = [A + H F E, 0; B_F C, A_F],  B̄ = [B, 0; 0, B_F D],  C̄ = [L, −C_F],  D̄ = 0.
#pragma once
#include <Eigen/Dense>

#include "hinf/models/plant.hpp"
#include "hinf/models/state_space.hpp"

namespace hinf::certify {

// F is j×k; an empty F (0×0) means the nominal system ΔA = 0. Throws Error(InvalidInput)
// on inconsistent dimensions of the plant, the filter or F.
// For an observer-form filter (filter.form) it is the n-state system of docs/maths.md
// (122)–(123) instead: (A + ΔA − K C, [B, −K D], L), built from the plant and filter.K; the
// uncertainty then acts on the error dynamics (H̄ = H, Ē = E); its filtered variant
// (filter.M) has the output row (L − L M C, [0, −L M D]) of docs/maths.md (141).
StateSpace error_system(const Plant& plant, const Filter& filter,
                        const Eigen::MatrixXd& F = Eigen::MatrixXd());

// How far an observer-form filter's realisation is from (A − K C, K, L, G) of docs/maths.md
// (121), or (A − K C, K, L − L M C, G) with D_F = L M for the filtered variant (140): the largest entrywise difference, each relative to the magnitude of the terms that
// form it (+∞ on a dimension mismatch). Rounding of A − K C gives ~1e-16.
double observer_form_mismatch(const Plant& plant, const Filter& filter);

}  // namespace hinf::certify
