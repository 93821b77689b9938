// The output files of a gyroless_attitude run directory (docs/experiments.md "Seed 002"):
// trajectory.csv (run 0, every filter), runs.csv and summary.json (every run) and the plots
// of the source's Figs. 1–9.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "hinf/common/atomic_file.hpp"
#include "hinf/sim/gyroless_run.hpp"
#include "hinf/sim/gyroless_scenario_yaml.hpp"

namespace hinf::sim {

// samples[f] = filter f's samples of run 0.
std::string format_gyroless_trajectory_csv(const GyrolessExperiment& e,
                                           const std::vector<std::vector<GyrolessSample>>& samples);
// stats[r][f] = filter f's window statistics in run r.
std::string format_gyroless_runs_csv(const GyrolessExperiment& e,
                                     const std::vector<std::vector<GyrolessFilterStatistics>>& stats,
                                     const std::vector<std::uint64_t>& seeds);
std::string format_gyroless_summary_json(const GyrolessExperiment& e,
                                         const std::vector<std::vector<GyrolessFilterStatistics>>& stats,
                                         const std::string& scenario_path, std::uint64_t seed);
// The source's Figs. 1–9 for run 0 into temporaries of `outputs`: fig1_torque.png (the true
// torque), fig2/fig3 the torque and attitude errors of the AEKF sweep, fig4/fig5 of the
// ASTEKF sweep, fig6/fig7 of the AAEKFs, fig8/fig9 the comparison of the named filters.
// Throws PlotError (plots.hpp).
void write_gyroless_plots(const std::string& dir, const GyrolessExperiment& e,
                          const std::vector<std::vector<GyrolessSample>>& samples, const std::string& title,
                          hinf::AtomicFileSet& outputs);

}  // namespace hinf::sim
