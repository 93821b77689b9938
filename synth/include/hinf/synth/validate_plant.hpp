// The shape and finiteness checks of a Plant, shared by every entry point that accepts one.
#pragma once
#include "hinf/models/plant.hpp"

namespace hinf::synth {

// Throws Error(InvalidInput) naming the matrix and the expected/actual dimensions,
// or a non-finite entry.
void validate_plant(const Plant& plant);

}  // namespace hinf::synth
