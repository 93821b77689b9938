// The failure of a run that cannot go on (every experiment family): exit 4 in hinf-sim.
#pragma once
#include <Eigen/Dense>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "hinf/common/error.hpp"

namespace hinf::sim {

// A run that cannot continue (non-finite truth, thrust from a diverged estimate): exit 4.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A named part [offset, offset + size) of a family's truth vector, for messages.
struct NamedPart {
  const char* name;
  Eigen::Index offset, size;
};

// Throws SimulationError "FAMILY: the truth became non-finite at sample K (t = T s): NAME
// = [...]" naming the first of `parts` of `x` with a NaN or infinite entry; returns if x is
// finite. Every family checks its truth at every sample with it, so no run ends with exit 0
// and NaN rows.
void require_finite_truth(const std::string& family, long sample, double t, const Eigen::Ref<const Eigen::VectorXd>& x,
                          std::initializer_list<NamedPart> parts);

// A runtime filter's refusal (std::invalid_argument, its message led by its class, "Ekf: Q has
// a non-finite entry") of the settings a scenario gave it, as Error(InvalidInput) led by the
// scenario's key instead ("filters.ekf: Q has a non-finite entry; ..."): `origin` says which
// scenario values it was built from.
hinf::Error scenario_settings_error(const std::string& key, const std::invalid_argument& refusal,
                                    const std::string& origin);

}  // namespace hinf::sim
