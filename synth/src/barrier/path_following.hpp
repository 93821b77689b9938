// Barrier path following for   minimise cᵀx  subject to  M(x) ⪯ −εI,  ‖x‖ < ρ
// (SPEC §2 solver notes). Phase I finds a strictly feasible point (minimise s with
// M(x) + εI ⪯ sI until s < 0); phase II follows the central path x*(t) of
// f_t = t·cᵀx + φ(x) with t ← μ·t, a tangent predictor, and Ipopt for centring,
// until the duality gap (N+1)/t is below relative_gap_tol·|cᵀx|.
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <string>

#include "hinf/synth/settings.hpp"
#include "hinf/synth/status.hpp"
#include "hinf/synth/synthesis.hpp"
#include "lmi/lmi_problem.hpp"

namespace hinf::barrier {

using synth::Settings;
using synth::SolverStatus;

using synth::IterationReport;

struct SdpSolution {
  Eigen::VectorXd x;
  SolverStatus status = SolverStatus::NotRun;
  std::string detail;            // human-readable reason for a non-Solved status
  int newton_total = 0, newton_phase1 = 0, centerings = 0;
  double t = 0;
  double objective = 0;          // cᵀx
  double gap = 0;                // bound on cᵀx − p*: (N+1)/t (+ λ²/t)
  double relative_gap = 0;       // gap/|cᵀx|
  double dual_bound = 0;         // tr(W M₀)/t with the margin removed: ≈ lower bound on p*
  double phase1_s = 0;           // final s of phase I (> 0: infeasible)
  double elapsed_s = 0;
};

using synth::IterationObserver;

// x0: optional starting point (size 0 = zero vector).
SdpSolution minimize_linear(const lmi::LmiProblem& lmi, const Eigen::VectorXd& c,
                            const Settings& settings, const Eigen::VectorXd& x0 = Eigen::VectorXd(),
                            const IterationObserver& observer = nullptr);

}  // namespace hinf::barrier
