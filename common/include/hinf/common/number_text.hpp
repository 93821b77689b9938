// Shortest decimal text of a double that reads back to the same value, for messages
// that name a user's value ("solver.lmi_margin = 1e-15: ...").
#pragma once
#include <string>

namespace hinf {

std::string number_text(double value);

}  // namespace hinf
