// hinf-sim's end-of-run table (docs/cli.md): a campaign's summary.json as text, one row per
// filter (or the controller's metrics), its headline metrics (RMS figures first) — one run's values,
// or mean ± std over several — and whether it converged or diverged. Formatting only.
#pragma once
#include <string>

namespace hinf::sim {

// The table of summary.json's `filters` (or `metrics`), "" if it has neither.
std::string summary_table(const std::string& summary_json);

}  // namespace hinf::sim
