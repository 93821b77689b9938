// Check 4 (docs/maths.md §7.4) without an SDP solver: the robust analysis LMI (50), i.e.
// Lemma 1 with the S-procedure, for a fixed filter, decided by the bounded-real lemma.
//
// With Ā, B̄, C̄ the nominal error system (docs/maths.md (9)–(11)), H̄ = [H; 0], Ē = [E, 0] and
// multiplier λ > 0, the analysis LMI
//     [ −P  PĀ            PB̄    0    PH̄  ]
//     [  ∗  −P + λĒᵀĒ      0    C̄ᵀ   0   ]
//     [  ∗   ∗           −γ²I   0    0   ]  < 0
//     [  ∗   ∗             ∗   −I    0   ]
//     [  ∗   ∗             ∗    ∗  −λI   ]
// is, after Schur complements on the −I and −P blocks and the congruence
// diag(I, I, I/γ, I/√λ), the discrete bounded-real inequality for
//     G_λ(z) = [C̄; √λ Ē] (zI − Ā)⁻¹ [B̄/γ, H̄/√λ],
// (plus the feedthrough [D̄/γ, 0; 0, 0] when the error system has one, the filtered observer's
// (141), whose output row then enters the LMI as in (142))
// so (strict bounded-real lemma) it is feasible in P for this λ iff Ā is Schur stable
// and ‖G_λ‖∞ < 1. G_λ = D G₁ D⁻¹ with D = diag(I, √λ I) on the uncertainty channel,
// so log σ_max(G_λ(e^{jθ})) is convex in log λ for every θ (Sezginer & Overton 1990)
// and ‖G_λ‖∞ is unimodal in log λ: a bracketing search with the slopes of log‖G_λ‖∞
// (from the top singular vectors at the peak frequency; tangent meeting points and
// slope secants) finds the best multiplier, with a golden-section search on the norm
// alone as the fallback. Each ‖G_λ‖∞ comes from the symplectic-pencil algorithm
// (hinf_norm.hpp), whose certified upper value is what is compared with 1.
#pragma once
#include <cmath>

#include <Eigen/Dense>

#include "hinf/certify/hinf_norm.hpp"
#include "hinf/models/plant.hpp"
#include "hinf/models/state_space.hpp"

namespace hinf::certify {

struct ScaledBoundedRealTest {
  bool feasible = false;     // certified: ‖G_λ‖∞ < 1 at lambda (analysis LMI feasible at γ)
  double lambda = 0;         // S-procedure multiplier (in the user's H, E units)
  // F block-diagonal (docs/maths.md §23): the multiplier of each block, λ·w_b (w the
  // block_weights() found); one entry, lambda, otherwise
  Eigen::VectorXd multipliers;
  double scaled_norm = 0;    // certified upper value of ‖G_λ‖∞ at lambda (< 1 iff feasible)
  int norm_evaluations = 0;  // H∞ norms computed
};

// The test for one filter: holds the nominal error system (docs/maths.md (9)–(11), which must
// be Schur stable, check 2 — Error(Infeasible) otherwise) and the scaled system's
// matrices, so that the many norms of a search share one set-up. Keeps a reference
// to `plant`.
class ScaledBoundedReal {
 public:
  ScaledBoundedReal(const hinf::Plant& plant, const hinf::StateSpace& error_system);

  // Certified upper value of ‖G_λ‖∞ at (γ, λ); λ is ignored for a certain plant.
  double scaled_norm(double gamma, double lambda);

  // stop_when_feasible: return at the first multiplier that certifies feasibility
  // (enough for the check); false: minimise ‖G_λ‖∞ over λ (to show how far from
  // feasible γ is). A plant without uncertainty has no multiplier: the test is
  // ‖C̄(zI − Ā)⁻¹B̄‖∞ < γ.
  // F block-diagonal: `start` (one positive multiplier per block, e.g. a synthesis's; may be
  // empty) gives the blocks' weights the search starts from, instead of all equal.
  ScaledBoundedRealTest test(double gamma, bool stop_when_feasible = true,
                             const Eigen::VectorXd& start = Eigen::VectorXd());

  // The smallest γ (to relative accuracy rel_tol, rounded up) with ‖G_λ‖∞ < 1 at the
  // fixed multiplier lambda, by regula falsi (Illinois) on (gamma_lo, gamma_hi]: gamma_hi
  // must pass;
  // gamma_lo is the nominal norm ‖C̄(zI − Ā)⁻¹B̄‖∞ (check 3's value), below which no γ
  // passes. Every γ it returns is certified: the analysis LMI is feasible there.
  double gamma_at_multiplier(double lambda, double gamma_lo, double gamma_hi, double rel_tol);

  int evaluations() const { return evaluations_; }
  // The relative multipliers w_b of F's blocks (λ_b = λ·w_b) that test() settled on; all 1
  // (one entry) when F is one block. scaled_norm and gamma_at_multiplier use them.
  const Eigen::VectorXd& block_weights() const { return weights_; }

 private:
  struct Slope {
    double norm = INFINITY;  // certified upper value of ‖G_λ‖∞
    double slope = 0;        // d log‖G_λ‖∞ / d log λ at the peak frequency
    bool slope_ok = false;
  };
  // ‖G_λ‖∞ at (γ, λ) to norm_tolerance, with its peak: the one place that scales B, C.
  hinf::certify::HinfNorm scaled_hinf_norm(double gamma, double lambda, double norm_tolerance);
  Slope scaled_norm_and_slope(double gamma, double log_lambda);
  // The best multiplier d = log λ found so far and its norm.
  struct Best {
    double d = 0, f = INFINITY;
    bool stop_when_feasible = true;
    void record(double dd, double ff) {
      if (ff < f) f = ff, d = dd;
    }
    bool done() const { return stop_when_feasible && f < 1.0; }
  };
  // The two searches of test(): over [d0 − w, d0 + w] (w = kLogLambdaHalfWidth).
  // slope_search returns true when it located the minimum (or settled the verdict).
  bool slope_search(double gamma, double d0, Best& best);
  void golden_section_search(double gamma, double d0, Best& best);
  // The search over λ for the current weights (slope search, golden-section fallback).
  void search_common_multiplier(double gamma, double d0, Best& best);
  // F block-diagonal: cyclic searches over each log w_b (b ≥ 1), each followed by the
  // search over λ, while they lower the norm (docs/maths.md §23).
  void search_block_weights(double gamma, Best& best);

  const hinf::Plant& plant_;
  hinf::StateSpace e_;
  int pq_ = 0;
  Eigen::MatrixXd B_, C_, D_;
  Eigen::VectorXd weights_;
  int evaluations_ = 0;
};

// One-shot form: ScaledBoundedReal(plant, error_system(plant, filter)).test(gamma, …).
ScaledBoundedRealTest scaled_bounded_real(const hinf::Plant& plant, const hinf::Filter& filter, double gamma,
                                          bool stop_when_feasible = true);

}  // namespace hinf::certify
