// A verified bracket of the optimum of   p* = inf { cᵀx : M(x) ≺ 0 }   (docs/maths.md §5.9):
// a lower bound from an explicitly constructed dual point Z ⪰ 0 with c + 𝒜*(Z) = 0
// (weak duality, eq. (113)) and an upper bound from a point x with M(x) ≺ 0, both
// definiteness claims verified by a shifted floating-point Cholesky test (Rump 2006).
// Every rounding error is bounded and subtracted, and the residual
// of the dual equalities is removed by an explicit correction whose size is bounded
// (eqs. (114)–(116)), so the bound holds for the strict LMI as posed — it does not use the
// solver's margin ε, its feasibility radius or its duality-gap estimate. Knows nothing of
// the barrier: it needs only the LMI data and primal points.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "hinf/lmi/lmi_problem.hpp"

namespace hinf::sdp {

struct DualBound {
  bool verified = false;        // lower_bound is a theorem (else it is −∞ and detail says why)
  double lower_bound = -1.0 / 0.0;  // ≤ p*, rounding and the residual correction included
  bool upper_verified = false;  // M(x) ≺ 0 verified at the given x: p* ≤ cᵀx
  double upper_bound = 1.0 / 0.0;   // cᵀx when upper_verified
  double dual_objective = 0;    // tr(Z M₀) of the computed Z (before the corrections)
  double residual_bound = 0;    // bound on ‖c + 𝒜*(Z)‖₂, rounding included
  double correction_bound = 0;  // bound on ‖D⁻¹ΔD⁻¹‖_F, Z − Δ exactly dual feasible (eq. (115))
  std::string detail;           // why the lower bound is not verified
};

// x: a strictly feasible point of the solver's problem (M(x) ⪯ −εI with ε = margin); the
// dual point is built from the slack there (docs/maths.md §5.9). basis_error: entrywise
// bounds |Mᵢ − M̂ᵢ|(row, col) ≤ value (upper triangle, as SparseEntry) between the LMI the
// caller means and the stored one, where forming the stored Mᵢ rounded; the bracket is
// then for the caller's LMI (M₀ is taken as exact). Costs O(p·N²) for the sparse basis and
// O(p³) for the smallest eigenvalue of the Gram matrix of the Mᵢ.
// path (optional): earlier centred points of the same path, oldest first
// (sdp::Solution::centred_path); their dual points, further inside the cone, are tried
// when the final one cannot be verified.
DualBound verified_bracket(const lmi::LmiProblem& lmi, const Eigen::VectorXd& c, const Eigen::VectorXd& x,
                           double margin, const std::vector<lmi::SparseEntry>& basis_error = {},
                           const std::vector<Eigen::VectorXd>& path = {});

// A verified certificate that M(x) ≺ 0 has no solution (docs/maths.md §5.9, eq. (118)):
// the bracket of phase I's problem   s* = inf { s : M(x) − sI ≺ 0 }   over (x, s). Its
// dual point is a Z ⪰ 0 with tr Z = 1 and tr(Z Mᵢ) = 0 for every i, so tr(Z M(x)) = tr(Z M₀)
// for all x; a verified lower_bound > 0 is therefore a theorem that no x makes M(x) ≺ 0.
// z: phase I's final point (x, s) with M(x) − sI ⪯ −εI (ε = margin); path: its earlier
// centred points, oldest first (sdp::Solution::phase1_path); basis_error as above.
DualBound verified_infeasibility(const lmi::LmiProblem& lmi, const Eigen::VectorXd& z, double margin,
                                 const std::vector<lmi::SparseEntry>& basis_error = {},
                                 const std::vector<Eigen::VectorXd>& path = {});

}  // namespace hinf::sdp
