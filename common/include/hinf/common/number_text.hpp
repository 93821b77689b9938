// Shortest decimal text of a double that reads back to the same value, for messages
// that name a user's value ("solver.lmi_margin = 1e-15: ...").
#pragma once
#include <string>

namespace hinf {

std::string number_text(double value);

// `digits` significant digits (printf's %g), for tables and summaries read by people.
std::string significant_text(double value, int digits);

}  // namespace hinf
