// Printing only: the output files of a tumbling_hold run (docs/experiments.md, "Seed 004").
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "hinf/common/atomic_file.hpp"
#include "hinf/sim/hold_run.hpp"

namespace hinf::sim {

struct HoldSummaryContext {
  std::string scenario_path;
  std::uint64_t seed = 0;
  std::string controller_origin;
  std::optional<double> gamma;
  Eigen::Vector3d feedforward = Eigen::Vector3d::Zero();
};

// trajectory.csv: one row per control sample: t, err_x..z (ρ − ρ*, m), vel_x..z (m/s),
// cmd_x..z (U, N; nan on the last sample, where no command is computed), force_x..z (mean
// applied force over [t_k, t_k+1), N), pulse_x..z (thruster state at t_k).
std::string format_hold_trajectory_csv(const HoldTrajectory& tr);
// runs.csv: one row per run with its metrics (an empty cell: none).
std::string format_hold_runs_csv(const std::vector<HoldRunResult>& runs);
// summary.json: top-level `metrics`, each a number (one run) or {mean, std, min, max, count}.
std::string format_hold_summary_json(const HoldScenario& s, const std::vector<HoldRunResult>& runs,
                                     const HoldSummaryContext& context);
// position.png, velocity.png, thrusters.png (the seed paper's three figures) from run 0.
// Throws PlotError (plots.hpp).
// DIR/error_norms.png (write_error_band_figure, plots.hpp): |ρ − ρ*| and |ρ̇| of every run (their
// traces) and run 0's (its trajectory), the steady-state start marked. Throws PlotError.
void write_hold_error_band(const std::string& dir, const std::vector<HoldRunResult>& runs, const HoldScenario& s,
                           const std::string& title, hinf::AtomicFileSet& outputs);

void write_hold_plots(const std::string& dir, const HoldTrajectory& tr, const std::string& title,
                      hinf::AtomicFileSet& outputs);

}  // namespace hinf::sim
