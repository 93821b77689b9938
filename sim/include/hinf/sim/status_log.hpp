// A line of progress for the user ("synthesising from PATH ..."): the library says what it
// is doing, the front end decides where, and whether, it is shown. Empty: silent. The
// library itself never prints.
#pragma once
#include <functional>
#include <string>

namespace hinf::sim {

using StatusLog = std::function<void(const std::string& line)>;

}  // namespace hinf::sim
