// The output files of a gps_ins_relative run directory (docs/experiments.md "Seed 003"):
// trajectory.csv (run 0, every filter), runs.csv and summary.json (every run).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "hinf/sim/gps_ins_run.hpp"
#include "hinf/sim/gps_ins_scenario_yaml.hpp"

namespace hinf::sim {

// samples[f] = filter f's samples of run 0.
std::string format_gps_ins_trajectory_csv(const GpsInsExperiment& e,
                                          const std::vector<std::vector<GpsInsSample>>& samples);
// stats[r][f] = filter f's window statistics in run r.
std::string format_gps_ins_runs_csv(const GpsInsExperiment& e,
                                    const std::vector<std::vector<GpsInsFilterStatistics>>& stats,
                                    const std::vector<std::uint64_t>& seeds);
std::string format_gps_ins_summary_json(const GpsInsExperiment& e,
                                        const std::vector<std::vector<GpsInsFilterStatistics>>& stats,
                                        const std::string& scenario_path, std::uint64_t seed);

}  // namespace hinf::sim
