// Theorem 1 of Sun et al. 2011 (the LMI docs/maths.md (18)) written once, block by block,
// as data for the generic LMI layer; and the robust analysis LMI docs/maths.md (50)
// (Lemma 1 with the S-procedure) for a fixed filter (check 4, docs/maths.md §7.4).
#pragma once
#include "hinf/models/plant.hpp"
#include "hinf/certify/dense_lmi.hpp"
#include "hinf/lmi/lmi_problem.hpp"

namespace hinf::synth {

struct Theorem1Lmi {
  lmi::LmiProblem lmi{std::vector<int>{}};
  lmi::VarId R, S, AFbar, BFbar, CFbar, g;
  std::vector<lmi::VarId> lambda;  // one per block of F (docs/maths.md §23); none without uncertainty
  lmi::VarId margin;  // only in the γ back-off problem (g fixed): M(x) ⪯ margin·I
};

// Blocks n, n, n, n, p, q, l, j (the last only with uncertainty). The plant is the scaled
// one (plant_scaling.hpp); the LMI is written for it as it is.
Theorem1Lmi build_theorem1(const hinf::Plant& plant);

// The γ back-off problem (docs/maths.md (44), [D6]): g = γ_b² fixed, and a scalar `margin` with
// M(x) ⪯ margin·I on every block; minimising `margin` maximises the LMI's margin.
Theorem1Lmi build_theorem1_backoff(const hinf::Plant& plant, double g_fixed);

// Entrywise bounds on |Mᵢ − M̂ᵢ| between LMI (18) and the stored one: only λ's EᵀE (block
// (3,3)) is a rounded product, |fl(EᵀE) − EᵀE| ≤ γ_k|E|ᵀ|E|; for sdp::verified_bracket.
std::vector<lmi::SparseEntry> theorem1_basis_error(const Theorem1Lmi& T, const hinf::Plant& plant);
// The same bound for any LMI whose diagonal block `block` holds Σ_b λ_b E_bᵀE_b in its
// leading n×n (Theorem 1, (50), (124)).
std::vector<lmi::SparseEntry> rounded_EtE_basis_error(const lmi::LmiProblem& lmi,
                                                     const std::vector<lmi::VarId>& lambda, int block,
                                                     const hinf::Plant& plant);

// One multiplier per block of F (docs/maths.md (18), §23), declared once (named "lambda"
// for one block, "lambda_1", "lambda_2", … otherwise); then λ_b·E_bᵀE_b added to the
// diagonal block `e_block` (E is the k×(its size) matrix there: E, or Ē = [E, 0]) and
// −λ_b·I on the block's rows of the diagonal block `h_block` (size j), each where the LMI
// writes it.
std::vector<lmi::VarId> declare_multipliers(lmi::LmiProblem& M, const hinf::Plant& plant);
void add_multiplier_EtE(lmi::LmiProblem& M, const hinf::Plant& plant, const std::vector<lmi::VarId>& lambda,
                        const Eigen::MatrixXd& E, int e_block);
void add_multiplier_identity(lmi::LmiProblem& M, const hinf::Plant& plant, const std::vector<lmi::VarId>& lambda,
                             int h_block);
// The diagonal blocks both filter LMIs end with, from block `first` (docs/maths.md (50),
// (124)): −g·I_p, −g·I_q, −I_l, then −λ_b·I on the multipliers' block when the plant is
// uncertain. With γ² fixed (*g_fixed, the back-off problem) −γ²·I are constants and every
// diagonal block gets −margin·I.
void add_filter_lmi_tail(lmi::LmiProblem& M, const hinf::Plant& plant, const double* g_fixed, lmi::VarId g,
                         lmi::VarId margin, const std::vector<lmi::VarId>& lambda, int first);
// The multipliers' values at x.
Eigen::VectorXd multiplier_values(const lmi::LmiProblem& M, const std::vector<lmi::VarId>& lambda,
                                  const Eigen::VectorXd& x);

// The Theorem-1 variables at a solution x of T's LMI, with g = γ² (fixed in the back-off
// problem, the objective otherwise).
certify::Theorem1Point theorem1_point(const Theorem1Lmi& T, const hinf::Plant& plant,
                                      const Eigen::VectorXd& x, double g);

// Filter recovery, docs/maths.md (22): A_F = S⁻¹Ā_F, B_F = S⁻¹B̄_F, C_F = C̄_F, by
// Cholesky solves with S. Throws Error(NumericalFailure) if S is not positive definite.
hinf::Filter recover_filter(const certify::Theorem1Point& pt);

struct AnalysisLmi {
  lmi::LmiProblem lmi{std::vector<int>{}};
  lmi::VarId P, g;
  std::vector<lmi::VarId> lambda;
};

// Blocks 2n, 2n, p+q, l, j (docs/maths.md (50)):
//   [ −P   PĀ₀        PB̄    0    PH̄  ]
//   [  ∗  −P+λĒᵀĒ     0     C̄ᵀ   0   ]
//   [  ∗   ∗         −gI    0    0   ]   < 0
//   [  ∗   ∗          ∗    −I    0   ]
//   [  ∗   ∗          ∗     ∗   −λI  ]
// with the error system of docs/maths.md (9)–(11), H̄ = [H; 0], Ē = [E, 0] (blocks n instead of 2n,
// H̄ = H, Ē = E, for an observer-form filter: (122)–(123)).
AnalysisLmi build_analysis_lmi(const hinf::Plant& plant, const hinf::Filter& filter);

}  // namespace hinf::synth
