// Synthesis settings: a flat struct, one documented default per field, one validate().
// Every field is set by the config's `solver:` section under its own name, but for `form`
// and `estimate` (the config's `filter.form`, `filter.estimate`).
#pragma once
#include <string>

#include "hinf/models/plant.hpp"

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
  // Strictness margin of the LMI, relative to the equilibrated problem: the solver
  // enforces −M(x) ⪰ lmi_margin·I (docs/maths.md (26), [D2], [D3]). Refused below 1e-14
  // (solver tolerance).
  double lmi_margin = 1e-12;
  // Stop when the barrier's duality gap (N+1)/t is below this fraction of γ².
  double relative_gap_tol = 1e-7;
  // Factor by which the barrier parameter t grows between centring steps.
  double barrier_growth = 50.0;
  // Feasibility radius on the equilibrated variables (LMI Lab's "feasradius").
  double feasibility_radius = 1e8;
  // Newton iterations allowed in one centring step (Ipopt's max_iter).
  int max_newton_per_centering = 60;
  // Total Newton iterations allowed in one solve (phase I + phase II).
  int max_iterations = 600;
  // Wall-clock limit for one solve, seconds.
  double time_limit_s = 600.0;
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
