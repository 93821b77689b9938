// Synthesis settings: one documented default per field, one validate(). The solver's options
// are its own struct (sdp::Options, as Ceres gives its inner solver its own options); the rest
// are the synthesis's and its certificate's. Every field is set by the config's `solver:`
// section under its own name, but for `form` and `estimate` (`filter.form`, `filter.estimate`).
#pragma once
#include <string>

#include "hinf/models/plant.hpp"
#include "hinf/sdp/path_following.hpp"

namespace hinf::synth {

// Which filter to synthesise (docs/maths.md §18.4): Auto takes Theorem 1's augmented filter
// when the plant is Schur stable and has no known input, the observer form otherwise.
enum class FormChoice { Auto, Augmented, Observer };

struct Settings {
  // The filter's formulation (config `filter.form: auto | augmented | observer`).
  FormChoice form = FormChoice::Auto;
  // The estimate an observer-form filter gives (config `filter.estimate: predicted | filtered`):
  // of z(k) from y(0..k−1), or from y(0..k) (docs/maths.md §18.6; observer form only).
  hinf::Estimate estimate = hinf::Estimate::Predicted;
  // The interior-point solver's own options (docs/maths.md §5), each documented with its
  // default in hinf/sdp/path_following.hpp and set by the config's `solver:` key of the same
  // name: lmi_margin (strictness −M(x) ⪰ ε·I on the equilibrated LMI, (26), [D2], [D3]; refused
  // below 1e-14, the solver's tolerance), relative_gap_tol, barrier_growth,
  // feasibility_radius, max_newton_per_centering, max_iterations, time_limit_s. The
  // synthesis passes them to the solver as they are; they are never written twice.
  sdp::Options solver;
  // Refuse (exit 2, before allocating) an SDP whose solve the solver's memory model
  // (hinf/sdp/memory_model.hpp) puts above this many MiB. The default leaves a third of
  // a 24 GiB machine free; raise it on a larger one.
  double max_memory_mb = 16384;
  // γ back-off (docs/maths.md §6, [D6]): if > 0, the filter is recovered at
  // γ_b = (1 + gamma_backoff)·γ* from the point of largest LMI margin (better-conditioned
  // S, R − S and gains). 0 = off.
  double gamma_backoff = 0.0;
  // Number of random admissible F(k) sampled in the Schur-stability check.
  int stability_samples = 64;
  // Seed for that sampling (checks are deterministic).
  unsigned seed = 1;
  // Print an iteration table to stderr.
  bool verbose = false;

  // Throws Error(InvalidInput) naming the offending field and value.
  void validate() const;
};

}  // namespace hinf::synth
