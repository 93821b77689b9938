// Schur stability of a matrix and sampled robust stability of the error system of
// docs/maths.md (11) over admissible uncertainties F (FᵀF ≤ I), certificate check 2
// (docs/maths.md (47)).
// Sampling is evidence, not proof: the robust guarantee is the analysis LMI (check 4).
#pragma once
#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "hinf/models/plant.hpp"

namespace hinf::certify {

// ρ(M) = max |λ_i(M)| (0 for an empty matrix). Throws Error(InvalidInput) if M is not
// square or not finite, Error(NumericalFailure) if the eigenvalue iteration fails.
double spectral_radius(const Eigen::MatrixXd& M);

// An eigenvalue of largest modulus (the first such in the solver's order), computed
// balanced; same errors as spectral_radius, and 0 for an empty matrix.
std::complex<double> dominant_eigenvalue(const Eigen::MatrixXd& M);

struct StabilitySample {
  double max_spectral_radius = 0;  // max over the samples of ρ(Ā(F))
  int samples = 0;                 // number of F evaluated (nominal included)
  Eigen::MatrixXd worst_F;         // the F attaining max_spectral_radius (j×k)
};

// The admissible F that check 2 samples, in order: F = 0 (an empty matrix); F = ±I (j×k,
// padded); F = ±e_a e_bᵀ for every (a, b) inside F's blocks; and `random_samples` random
// F = G/σ_max(G), G a j×k standard Gaussian matrix drawn from std::mt19937_64(seed) by the
// Box–Muller transform (deterministic on every platform), each block scaled to norm 1
// when F is block-diagonal (docs/maths.md §23). Without uncertainty only F = 0.
std::vector<Eigen::MatrixXd> admissible_samples(const Plant& plant, int random_samples, unsigned seed);

// ρ(Ā(F)) over admissible_samples(plant, random_samples, seed).
StabilitySample sampled_robust_stability(const Plant& plant, const Filter& filter,
                                         int random_samples, unsigned seed);


// ρ(Ā(F)) for each F in `Fs` (each j×k with ‖F‖₂ ≤ 1 + 1e-12, else Error(InvalidInput)).
// The nominal F = 0 is NOT added implicitly.
StabilitySample sampled_robust_stability(const Plant& plant, const Filter& filter,
                                         const std::vector<Eigen::MatrixXd>& Fs);

}  // namespace hinf::certify
