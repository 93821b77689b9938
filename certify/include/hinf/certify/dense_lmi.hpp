// Dense, direct assembly of LMI (18) (and of the observer-form LMI (124)) of docs/maths.md in the user's units, written
// independently of the generic LMI layer the solver uses, so that the certificate
// does not trust the solver's own data structures (docs/maths.md §7: independent checks).
#pragma once
#include <Eigen/Dense>

#include "hinf/models/plant.hpp"

namespace hinf::certify {

struct Theorem1Point {
  Eigen::MatrixXd R, S, AF_bar, BF_bar, CF_bar;
  Eigen::VectorXd lambda;  // one multiplier per block of F (docs/maths.md §23); empty without uncertainty
  double g = 0;            // γ²
};

// LMI (18) of docs/maths.md at a point (blocks n, n, n, n, p, q, l[, j]).
Eigen::MatrixXd theorem1_matrix(const hinf::Plant& plant, const Theorem1Point& x);

// The observer-form LMI (124) of docs/maths.md at a point (blocks n, n, p, q, l[, j]).
struct ObserverPoint {
  Eigen::MatrixXd P, Y;    // Y = P K
  Eigen::MatrixXd N;       // N = L M, l×m, filtered variant only (docs/maths.md (142)); empty: predictor
  Eigen::VectorXd lambda;  // one multiplier per block of F; empty without uncertainty
  double g = 0;            // γ²
};
Eigen::MatrixXd observer_lmi_matrix(const hinf::Plant& plant, const ObserverPoint& x);

struct DefinitenessCheck {
  double max_eig = 0;           // largest eigenvalue of M (to relative accuracy when M ≺ 0)
  double max_eig_relative = 0;  // max_eig / ‖M‖₂
  // Cholesky of −M − margin·I, Jacobi-scaled (a congruence: same inertia), succeeded
  bool negative_definite = false;
};
// The multiplier terms of (18), (50), (124) for one multiplier per block of F (§23):
// EᵀΛE = Σ_b λ_b E_bᵀE_b (n×n) and Λ = diag(λ_b I) (j×j). Not structured: λ₀EᵀE, λ₀I.
struct MultiplierTerms {
  Eigen::MatrixXd EtLE, Lambda;
};
MultiplierTerms multiplier_terms(const hinf::Plant& plant, const Eigen::VectorXd& lambda);

DefinitenessCheck check_negative_definite(const Eigen::MatrixXd& M, double margin);

}  // namespace hinf::certify
