// Shortest decimal text of a double that reads back to the same value, for messages
// that name a user's value ("solver.lmi_margin = 1e-15: ...").
#pragma once
#include <string>

namespace hinf {

std::string number_text(double value);

// `digits` significant digits (printf's %g), for tables and summaries read by people.
std::string significant_text(double value, int digits);

// A duration for people: "0.12 s", "45 s", "3.2 min", "1.5 h" (two significant digits).
std::string duration_text(double seconds);

// The one form a number takes in every input of the tool (a YAML value, a number inside an
// expression, a command-line value): YAML 1.2's core-schema float,
// [-+]? ( \. [0-9]+ | [0-9]+ ( \. [0-9]* )? ) ( [eE] [-+]? [0-9]+ )?. No hexadecimal
// (strtod's 0x1p3), no inf/nan words, no trailing text.
bool is_decimal_number(const std::string& text);

}  // namespace hinf
