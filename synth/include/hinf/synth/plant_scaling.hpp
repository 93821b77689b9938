// The scaling the synthesis applies before it solves (docs/maths.md §4.4, eqs. (108)–(112)):
// state coordinates x = D x̃ (diagonal balancing of [A, B, H; C; L; E]), measurement units
// ỹ = T y, a common input unit (w, v) = σ_in·(w̃, ṽ), a common output unit z̃ = σ_z·z, and
// the uncertainty split H̃ = D⁻¹H·s, Ẽ = E·D/s. Every factor is a power of two, so the
// scaled plant, the filter mapped back and γ = γ̃/(σ_in·σ_z) are exact: the same problem in
// other units. Only scalings that leave the problem unchanged are used (w and v share one
// unit because ‖(w, v)‖ mixes them; F one because ‖F‖ ≤ 1 is not invariant otherwise).
#pragma once
#include <string>

#include <Eigen/Dense>

#include "hinf/models/plant.hpp"

namespace hinf::synth {

struct PlantScaling {
  Eigen::VectorXd state;        // d: x = diag(d)·x̃
  Eigen::VectorXd measurement;  // t: ỹ = diag(t)·y
  double input = 1;             // σ_in
  double output = 1;            // σ_z
  double uncertainty = 1;       // s
  // γ̃ = gamma_factor()·γ for the same filter
  double gamma_factor() const { return input * output; }
  // "x: 2^[..], y: 2^[..], w,v: 2^k, z: 2^k, H/E: 2^k" (for -v and the gains file)
  std::string summary() const;
};

// The identity scaling for a plant's dimensions.
PlantScaling identity_scaling(const hinf::Plant& plant);

// The power of two nearest to 1/v (1 for v = 0 or non-finite): a unit that brings v to ~1
// (the plant's and the generalised plant's equilibration, controller_scaling.cpp).
double unit_for(double v);
// The scaling chosen from the plant's data: alternating rounds of state balancing, unit
// row norms of [C D], and unit norms of [B; D] and L, then s with ‖H̃‖ ≈ ‖Ẽ‖.
PlantScaling choose_scaling(const hinf::Plant& plant);
// The identity but for s with ‖sH‖ ≈ ‖E/s‖ (docs/maths.md (24)).
PlantScaling uncertainty_split(const hinf::Plant& plant);

hinf::Plant scaled_plant(const hinf::Plant& plant, const PlantScaling& s);
// A filter for the user's plant in the scaled units, and back (exact inverses).
hinf::Filter scaled_filter(const hinf::Filter& user, const PlantScaling& s);
hinf::Filter user_filter(const hinf::Filter& scaled, const PlantScaling& s);

}  // namespace hinf::synth
