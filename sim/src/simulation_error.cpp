#include "hinf/sim/simulation_error.hpp"

#include <sstream>

#include "hinf/common/number_text.hpp"

namespace hinf::sim {

void require_finite_truth(const std::string& family, long sample, double t, const Eigen::Ref<const Eigen::VectorXd>& x,
                          std::initializer_list<NamedPart> parts) {
  if (x.allFinite()) return;
  std::ostringstream os;
  os << family << ": the truth became non-finite at sample " << sample << " (t = " << number_text(t) << " s)";
  for (const NamedPart& p : parts) {
    const auto part = x.segment(p.offset, p.size);
    if (part.allFinite()) continue;
    os << ": " << p.name << " = [";
    for (Eigen::Index i = 0; i < part.size(); ++i) os << (i > 0 ? ", " : "") << number_text(part(i));
    os << "]";
    break;
  }
  os << " (the scenario's values or its integration step make the dynamics overflow)";
  throw SimulationError(os.str());
}

hinf::Error scenario_settings_error(const std::string& key, const std::invalid_argument& refusal,
                                    const std::string& origin) {
  std::string what = refusal.what();
  // drop the leading "Class: " or "hinf::runtime::Class: " (a word with :: but no space)
  const std::size_t colon = what.find(": ");
  if (colon != std::string::npos && what.find(' ') > colon) what.erase(0, colon + 2);
  return hinf::Error(hinf::ErrorCode::InvalidInput, key + ": " + what + " (built from " + origin + ")");
}

}  // namespace hinf::sim
