// summary_table (summary_table.hpp).
#include "hinf/sim/summary_table.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "summary_json.hpp"

namespace hinf::sim {
namespace {

// The metrics shown per row: the first numeric ones of the family's summary.
constexpr std::size_t kTableMetrics = 3;

// A number, or the statistics of one over the runs (stats_json: a numeric mean and std); not a
// list of them (the manoeuvring family's settling times per manoeuvre), not a setting's text.
bool is_metric(const Json& v) {
  if (v.is_object())
    return v.contains("mean") && v["mean"].is_number() && v.contains("std") && v["std"].is_number();
  return v.is_number() && !v.is_boolean();
}

std::string cell(const Json& v) {
  char buf[64];
  if (v.is_object())
    std::snprintf(buf, sizeof buf, "%.4g ± %.2g", v["mean"].get<double>(), v["std"].get<double>());
  else
    std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());
  return buf;
}

// "converged", "DIVERGED at T s", "K of N runs diverged", or "".
std::string outcome(const Json& m) {
  if (m.contains("diverged_runs") && m["diverged_runs"].is_number())
    return m["diverged_runs"].get<long>() > 0 ? std::to_string(m["diverged_runs"].get<long>()) + " runs diverged"
                                              : std::string("none diverged");
  if (m.contains("diverged") && m["diverged"].is_boolean() && m["diverged"].get<bool>()) {
    const Json& at = m.contains("diverged_at_s") ? m["diverged_at_s"] : Json(nullptr);
    return at.is_number() ? "DIVERGED at " + cell(at) + " s" : std::string("DIVERGED");
  }
  if (m.contains("converged") && m["converged"].is_boolean()) return m["converged"].get<bool>() ? "converged" : "not converged";
  return "";
}

// Characters on screen (UTF-8: '±' is two bytes, one column).
std::size_t columns(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

void pad(std::string& line, std::size_t width) {
  const std::size_t n = columns(line);
  line.append(n < width ? width - n : 1, ' ');
}

// The metrics of a row to show: the summary's own `headline_metrics` when it names them;
// otherwise RMS figures first, then the others, in the summary's order, leaving out per-axis
// variants of one already taken (attitude_rms_deg_roll after attitude_rms_deg).
std::vector<std::string> headline_metrics(const Json& summary, const Json& row) {
  std::vector<std::string> names;
  if (summary.contains("headline_metrics") && summary["headline_metrics"].is_array()) {
    for (const Json& n : summary["headline_metrics"])
      if (n.is_string() && names.size() < kTableMetrics) names.push_back(n.get<std::string>());
    return names;
  }
  for (const bool rms : {true, false})
    for (auto it = row.begin(); it != row.end() && names.size() < kTableMetrics; ++it) {
      const std::string& k = it.key();
      if (!is_metric(it.value()) || (k.find("rms") != std::string::npos) != rms) continue;
      bool variant = false;
      for (const auto& n : names) variant |= k.rfind(n, 0) == 0;
      if (!variant) names.push_back(k);
    }
  return names;
}

}  // namespace

std::string summary_table(const std::string& summary_json) {
  const Json s = Json::parse(summary_json);
  Json rows = Json::object();
  if (s.contains("filters") && s["filters"].is_object()) rows = s["filters"];
  else if (s.contains("metrics") && s["metrics"].is_object()) rows["controller"] = s["metrics"];
  if (rows.empty()) return "";
  const std::vector<std::string> names = headline_metrics(s, *rows.begin());
  constexpr std::size_t kName = 18, kCell = 22;
  std::string out = "";
  pad(out, kName);
  for (const auto& n : names) {
    out += n;
    pad(out, kName + kCell * (&n - names.data() + 1));
  }
  out += "\n";
  for (auto row = rows.begin(); row != rows.end(); ++row) {
    std::string line = row.key();
    pad(line, kName);
    for (std::size_t k = 0; k < names.size(); ++k) {
      const Json& v = row.value().contains(names[k]) ? row.value()[names[k]] : Json(nullptr);
      line += is_metric(v) ? cell(v) : std::string("-");
      pad(line, kName + kCell * (k + 1));
    }
    out += line + outcome(row.value()) + "\n";
  }
  return out;
}

}  // namespace hinf::sim
