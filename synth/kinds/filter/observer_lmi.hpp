// The observer-form H∞ filter LMI (docs/maths.md (124)) written once, block by block, as
// data for the generic LMI layer: the bounded-real lemma with the S-procedure for the error
// dynamics (122) of x̂(k+1) = A x̂ + G u + K(y − C x̂), linear in (P, Y = P K, λ, γ²); for the
// filtered estimate ẑ(k|k) = L x̂(k|k) (§18.6) also in N = L M, the output row being (142).
#pragma once
#include <optional>

#include "hinf/certify/dense_lmi.hpp"
#include "hinf/lmi/lmi_problem.hpp"
#include "hinf/models/plant.hpp"

namespace hinf::synth {

struct ObserverLmi {
  lmi::LmiProblem lmi{std::vector<int>{}};
  lmi::VarId P, Y, g;
  std::optional<lmi::VarId> N;     // filtered variant only (docs/maths.md (142))
  std::vector<lmi::VarId> lambda;  // one per block of F (docs/maths.md §23); none without uncertainty
  lmi::VarId margin;           // only in the γ back-off problem (g fixed)
};

// Blocks n, n, p, q, l (, j with uncertainty). The plant is the scaled one.
ObserverLmi build_observer_lmi(const hinf::Plant& plant, hinf::Estimate estimate = hinf::Estimate::Predicted);
// The γ back-off problem (docs/maths.md §6 applied to (124)): g fixed, M(x) ⪯ margin·I.
ObserverLmi build_observer_lmi_backoff(const hinf::Plant& plant, double g_fixed,
                                       hinf::Estimate estimate = hinf::Estimate::Predicted);

// Entrywise bounds on |Mᵢ − M̂ᵢ| (λ's rounded EᵀE in block (1,1)); for sdp::verified_bracket.
std::vector<lmi::SparseEntry> observer_basis_error(const ObserverLmi& O, const hinf::Plant& plant);

certify::ObserverPoint observer_point(const ObserverLmi& O, const hinf::Plant& plant, const Eigen::VectorXd& x,
                                      double g);

// Recovery (docs/maths.md (125)): K = P⁻¹ Y by a Cholesky solve, and the filter
// A_F = A − K C, B_F = K, C_F = L, G_F = G (form Observer); filtered (pt.N set, (144)):
// M = L⁺ N (L of full row rank, so L M = N), C_F = L − L M C, D_F = L M. Throws
// Error(NumericalFailure) if P is not positive definite.
hinf::Filter recover_observer(const certify::ObserverPoint& pt, const hinf::Plant& plant);

}  // namespace hinf::synth
