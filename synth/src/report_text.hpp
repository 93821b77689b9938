// Numbers in the problem kinds' reports (synth/kinds/*/…_report.cpp): the text and the
// JSON value of a double as every report prints it.
#pragma once
#include <cmath>
#include <cstdlib>
#include <string>
#include <nlohmann/json.hpp>

#include "hinf/common/number_text.hpp"

namespace hinf::synth {

using Json = nlohmann::ordered_json;  // keys in the order written

// "%.10g"-like: ten significant digits.
inline std::string num(double v) { return hinf::significant_text(v, 10); }
// A number in JSON: the double itself (nlohmann writes the shortest digits that read back
// bit for bit); null if not finite.
inline Json json_num(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }
// One line of JSON; a path that is not UTF-8 is written with U+FFFD rather than refused.
inline std::string json_line(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace hinf::synth
