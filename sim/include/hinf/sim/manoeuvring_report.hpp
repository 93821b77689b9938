// The output files of a manoeuvring_target run directory (docs/experiments.md "Seed 001"):
// trajectory.csv (run 0, every filter), runs.csv and summary.json (every run) and the plots of
// the source's Figs. 4–5 (position, velocity and manoeuvre errors with ±3σ bands).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "hinf/common/atomic_file.hpp"
#include "hinf/sim/manoeuvring_run.hpp"
#include "hinf/sim/manoeuvring_scenario_yaml.hpp"

namespace hinf::sim {

// samples[f] = filter f's samples of run 0.
std::string format_manoeuvring_trajectory_csv(const ManoeuvringExperiment& e,
                                              const std::vector<std::vector<ManoeuvringSample>>& samples);
// stats[r][f] = filter f's statistics in run r.
std::string format_manoeuvring_runs_csv(const ManoeuvringExperiment& e,
                                        const std::vector<std::vector<ManoeuvringFilterStatistics>>& stats,
                                        const std::vector<std::uint64_t>& seeds);
std::string format_manoeuvring_summary_json(const ManoeuvringExperiment& e,
                                            const std::vector<std::vector<ManoeuvringFilterStatistics>>& stats,
                                            const std::string& scenario_path, std::uint64_t seed);
// Per filter F: F_position_error.png, F_velocity_error.png, F_manoeuvre_error.png (run 0),
// into temporaries of `outputs`. Throws PlotError (plots.hpp).
void write_manoeuvring_plots(const std::string& dir, const ManoeuvringExperiment& e,
                             const std::vector<std::vector<ManoeuvringSample>>& samples, const std::string& title,
                             hinf::AtomicFileSet& outputs);

}  // namespace hinf::sim
