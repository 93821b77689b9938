// A continuous-time controller flown at a period T, and the loop it makes with the plant
// sampled at T (docs/maths.md (161a)–(161c)): the controller discretised by Tustin's rule
// (161) or a zero-order hold on y, the generalised plant by a zero-order hold on w and u (held
// over the sample, as a DAC holds u), y and z read at the sample instants. The sampled loop's
// ℓ2 gain from w to z is what a discrete certificate proves about the controller as flown.
#pragma once
#include <string>

#include "hinf/models/controller.hpp"
#include "hinf/models/generalised_plant.hpp"

namespace hinf::synth {

enum class ControllerSampling { Tustin, ZeroOrderHold };

inline const char* to_string(ControllerSampling m) { return m == ControllerSampling::Tustin ? "tustin" : "zoh"; }

// Error(InvalidInput) naming `key` ("--tustin", "--zoh") unless T is positive and finite.
void require_sample_period(double T, const std::string& key);

// The controller at period T: Tustin's rule (161), or the zero-order hold (161a),
// A_d = e^{A_K T}, B_d = ∫₀ᵀ e^{A_K s} ds B_K, C_d = C_K, D_d = D_K.
Controller sample_controller(const Controller& K, double T, ControllerSampling method);

// The generalised plant at the sample instants (161b): [A_d, Γ] from exp(T [A, I; 0, 0]),
// B1_d = Γ B1, B2_d = Γ B2, C1, C2, D11, D12, D21 kept; time discrete, sample_time T. Throws
// Error(InvalidInput) naming `period_key` when T ‖A‖ is beyond the zero-order hold's accuracy
// (models/discretise.hpp) or the sampled matrices are not finite.
GeneralisedPlant sample_generalised_plant(const GeneralisedPlant& P, double T, const char* period_key);

// The uncertainty channel of the sampled plant (161c): p held over the sample like u,
// H_d = Γ H, E kept.
UncertaintyChannel sample_channel(const GeneralisedPlant& P, const UncertaintyChannel& channel, double T);

}  // namespace hinf::synth
