// The output files of a gps_ins_relative run directory (docs/experiments.md "Seed 003"):
// trajectory.csv (run 0, every filter), runs.csv and summary.json (every run), table1.csv
// (the source's Table 1) and the plots of the source's Figs. 1–4.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "hinf/common/atomic_file.hpp"
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
// campaigns[i][r][f] = filter f's statistics in run r of the campaign whose truth has the
// products-of-inertia fraction fractions[i]. One row per fraction and filter: the median over
// the runs of each axis's window maximum (attitude as 3-1-2 roll, pitch, yaw in deg; rate and
// bias in deg/s), the layout of the source's Table 1, and the median of the runs' mean NEES.
std::string format_gps_ins_table1_csv(const GpsInsExperiment& e, const std::vector<double>& fractions,
                                      const std::vector<std::vector<std::vector<GpsInsFilterStatistics>>>& campaigns);
// Draws the source's Figs. 1–4 for run 0 over the steady-state window — DIR/fig1_position.png,
// fig2_velocity.png, fig3_attitude.png, fig4_rate.png: each component's error and ±3σ per
// filter — into temporaries of `outputs`. Throws PlotError (plots.hpp).
void write_gps_ins_plots(const std::string& dir, const GpsInsExperiment& e,
                         const std::vector<std::vector<GpsInsSample>>& samples, const std::string& title,
                         hinf::AtomicFileSet& outputs);

}  // namespace hinf::sim
