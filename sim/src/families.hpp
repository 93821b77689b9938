// What the experiment families share (private to sim/): their accessors, listed once in
// family_registry.cpp, and the plots' titles.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "hinf/sim/family.hpp"
#include "hinf/sim/monte_carlo.hpp"

namespace hinf::sim::families {

const Family& hill();                // sim/families/hill
const Family& tumbling_hold();       // sim/families/tumbling_hold
const Family& gps_ins_relative();    // sim/families/gps_ins_relative
const Family& gyroless_attitude();   // sim/families/gyroless_attitude
const Family& manoeuvring_target();  // sim/families/manoeuvring_target
const Family& linear_plant();        // sim/families/linear_plant

// The plots' titles (issue "A tool people enjoy"): the scenario file's stem, the seed and the
// run count ("gps-ins-flyaround, seed 1, 20 runs"); a family's figures say what they show.
inline std::string plot_title(const std::string& stem, std::uint64_t seed, long runs) {
  return stem + ", seed " + std::to_string(seed) + ", " + std::to_string(runs) + (runs == 1 ? " run" : " runs");
}

}  // namespace hinf::sim::families
