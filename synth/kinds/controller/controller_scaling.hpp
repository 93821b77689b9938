// Equilibration of a generalised plant by powers of two (docs/maths.md (154)), so that the
// controller LMI is solved on a well-scaled problem and the result mapped back exactly:
//   x = D x̃ (states, TB01ID balancing),   t̃ = ω t (time, continuous only),
//   u = S_u ũ,   y = S_y ỹ,   w = s_w w̃,   z̃ = z / s_z.
// Every factor is a power of two, so the scaled plant and the maps back are exact.
#pragma once
#include <Eigen/Dense>

#include "hinf/models/controller.hpp"
#include "hinf/models/generalised_plant.hpp"

namespace hinf::synth {

struct ControllerScaling {
  Eigen::VectorXd state;  // d
  double time = 1;        // ω (1 in discrete time)
  Eigen::VectorXd u, y;   // diagonals of S_u, S_y
  double w = 1, z = 1;    // s_w, s_z
  // γ of the user's plant from γ̃ of the scaled one: γ = γ̃ s_z / s_w.
  double gamma_factor() const { return z / w; }
};

ControllerScaling choose_controller_scaling(const hinf::GeneralisedPlant& P);
hinf::GeneralisedPlant scaled_generalised_plant(const hinf::GeneralisedPlant& P, const ControllerScaling& s);
// The controller of the user's plant from one of the scaled plant:
//   A_K = ω Ã_K,  B_K = ω B̃_K S_y⁻¹,  C_K = S_u C̃_K,  D_K = S_u D̃_K S_y⁻¹.
hinf::Controller unscaled_controller(const hinf::Controller& K, const ControllerScaling& s);

}  // namespace hinf::synth
