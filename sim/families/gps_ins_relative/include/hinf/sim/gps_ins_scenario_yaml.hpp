// Reading a `scenario: gps_ins_relative` file (docs/experiments.md "Seed 003", which lists
// the keys) with the project's strict YAML reader: unknown keys, bad values and
// an inconsistent setup are hinf::Error(InvalidInput) naming file:line:col and the key path.
// Angles are in degrees in the file (keys *_deg, *_deg_s, *_deg_h), SI inside.
#pragma once
#include <string>
#include <vector>

#include "hinf/sim/gps_ins_run.hpp"
#include "hinf/sim/gps_ins_scenario.hpp"

namespace hinf::sim {

// The most filters one scenario may run side by side.
constexpr int kMaxGpsInsFilters = 8;

struct GpsInsExperiment {
  std::string path;
  GpsInsScenario scenario;
  std::vector<GpsInsFilterSettings> filters;  // in the file's order
  GpsInsRunOptions options;                   // window, initial error (on_sample unset)
  bool plots = true;
  // metrics.table1_products_fractions: the truth's products-of-inertia fractions p of
  // table1.csv (the source's Table 1), each a Monte-Carlo campaign with the same seeds;
  // empty: no table1.csv.
  std::vector<double> table1_fractions;
};

GpsInsExperiment parse_gps_ins_scenario(const std::string& yaml_text, const std::string& source_name);

}  // namespace hinf::sim
