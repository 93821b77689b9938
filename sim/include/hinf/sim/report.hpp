// Printing only: the output files of hinf-sim (docs/experiments.md, "Output files").
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hinf/sim/run.hpp"
#include "hinf/sim/scenario.hpp"

namespace hinf::sim {

// trajectory.csv: one row per step, doubles with 17 significant digits ("nan" after a
// filter diverged). Columns: t, true_x … true_vz, meas_x meas_y meas_z, meas_rho meas_alpha
// meas_beta, thrust_x thrust_y thrust_z, then <filter>_x … <filter>_vz per filter.
std::string format_trajectory_csv(const Trajectory& trajectory);

// runs.csv: one row per Monte-Carlo run: run, seed, then per filter its metrics
// (empty cell = none: diverged, or never converged) and diverged (0/1).
std::string format_runs_csv(const std::vector<RunResult>& runs);

struct GainsInfo {
  std::string origin;
  std::optional<double> gamma;
};

struct SummaryContext {
  std::string scenario_path;
  std::uint64_t seed = 0;
  std::map<std::string, GainsInfo> gains;  // for hinf / published
};

// summary.json. One run: each metric a number (or null with the reason alongside);
// several runs: each metric {mean, std, min, max, count} over the runs that have it.
// Throws std::logic_error rather than print a non-finite number.
std::string format_summary_json(const Scenario& scenario, const std::vector<RunResult>& runs,
                                const SummaryContext& context);

}  // namespace hinf::sim
