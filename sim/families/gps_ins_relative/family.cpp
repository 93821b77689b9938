// `scenario: gps_ins_relative` (docs/experiments.md "Seed 003"): the Monte-Carlo runs of every
// configured filter on each run's one measurement stream; trajectory.csv (run 0), runs.csv,
// summary.json, the plots of Figs. 1–4 and, with metrics.table1_products_fractions, table1.csv
// (one campaign per fraction, same seeds).
#include <algorithm>

#include "hinf/common/number_text.hpp"

#include "gps_ins_report.hpp"

namespace hinf::sim::families {
namespace {

using GpsIns = StreamFamily<GpsInsExperiment, GpsInsFilterStatistics, GpsInsSample>;
using Campaign = GpsIns::Functions::Campaign;

void shorten_gps_ins(GpsInsExperiment& e, double duration) {
  e.scenario.duration = duration;
  e.options.window_end = std::min(e.options.window_end, duration);
  if (e.options.window_start >= e.options.window_end) e.options.window_start = e.options.window_end / 2;
}

const GpsIns::Functions& functions();

// table1.csv: one campaign per table-1 fraction, the scenario's own where the fraction is its own.
void table1(const CampaignRequest& r, const GpsInsExperiment& e, const Campaign& own,
            std::vector<std::pair<std::string, std::string>>& files) {
  if (e.table1_fractions.empty()) return;
  std::vector<Campaign> campaigns;
  const auto own_fraction = [&](double p) { return p == e.scenario.inertia_products_fraction; };
  const long total = 1 + std::count_if(e.table1_fractions.begin(), e.table1_fractions.end(),
                                       [&](double p) { return !own_fraction(p); });
  long number = 1;
  for (double p : e.table1_fractions) {
    if (own_fraction(p)) {
      campaigns.push_back(own);
      continue;
    }
    if (r.on_campaign)
      r.on_campaign("campaign " + std::to_string(++number) + " of " + std::to_string(total) +
                    ": table 1 at inertia_products_fraction = " + number_text(p));
    GpsInsScenario scenario = e.scenario;
    scenario.inertia_products_fraction = p;
    campaigns.push_back(stream_campaign(functions(), r, e, scenario, nullptr));
  }
  files.emplace_back("table1.csv", format_gps_ins_table1_csv(e, e.table1_fractions, campaigns));
}

const GpsIns::Functions& functions() {
  static const GpsIns::Functions f{"gps_ins_relative", parse_gps_ins_scenario, shorten_gps_ins, run_gps_ins,
                                   gps_ins_outputs(), table1};
  return f;
}

}  // namespace

const Family& gps_ins_relative() {
  static const GpsIns family(functions());
  return family;
}

}  // namespace hinf::sim::families
