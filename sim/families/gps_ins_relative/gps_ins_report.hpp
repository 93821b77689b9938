// The output files of a gps_ins_relative run directory (docs/experiments.md "Seed 003"):
// trajectory.csv (run 0, every filter), runs.csv and summary.json (every run), table1.csv
// (the source's Table 1) and the plots of the source's Figs. 1–4.
// Private to the family (its family.cpp reads the table; sim/src/stream_family.hpp).
#pragma once
#include <string>
#include <vector>

#include "hinf/sim/gps_ins_run.hpp"
#include "hinf/sim/gps_ins_scenario_yaml.hpp"
#include "stream_family.hpp"

namespace hinf::sim {

// campaigns[i][r][f] = filter f's statistics in run r of the campaign whose truth has the
// products-of-inertia fraction fractions[i]. One row per fraction and filter: the median over
// the runs of each axis's window maximum (attitude as 3-1-2 roll, pitch, yaw in deg; rate and
// bias in deg/s), the layout of the source's Table 1, and the median of the runs' mean NEES.
std::string format_gps_ins_table1_csv(const GpsInsExperiment& e, const std::vector<double>& fractions,
                                      const std::vector<std::vector<std::vector<GpsInsFilterStatistics>>>& campaigns);

namespace families {

const StreamOutputs<GpsInsExperiment, GpsInsFilterStatistics, GpsInsSample>& gps_ins_outputs();

}  // namespace families
}  // namespace hinf::sim
