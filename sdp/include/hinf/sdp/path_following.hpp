// The barrier interior-point method for   minimise cᵀx  subject to  M(x) ⪯ −εI,  ‖x‖ < ρ
// (docs/maths.md §5). Phase I finds a strictly feasible point (minimise s with
// M(x) + εI ⪯ sI until s < 0); phase II follows the central path x*(t) of
// f_t = t·cᵀx + φ(x) with t ← μ·t, a tangent predictor, and Newton centring (Ipopt, then
// QR Newton steps at the end of the path), until the certified gap is below
// relative_gap_tol·|cᵀx|. Knows nothing of the application that built the LMI.
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "hinf/lmi/lmi_problem.hpp"
#include "hinf/sdp/status.hpp"

namespace hinf::sdp {

// The solver's own options (as Ceres's Minimizer::Options), built by the caller from its
// settings; each field's meaning and default is documented here once.
struct Options {
  double lmi_margin = 1e-12;             // ε: the solver enforces −M(x) ⪰ ε·I
  double relative_gap_tol = 1e-7;        // stop when the certified gap ≤ this·|cᵀx|
  double barrier_growth = 50.0;          // μ: t grows by at most this factor per centring
  double feasibility_radius = 1e8;       // ρ: the ball ‖x‖ < ρ that bounds the barrier
  int max_newton_per_centering = 60;     // Newton iterations allowed in one centring (the first of a phase: 4x)
  int max_iterations = 600;              // Newton iterations allowed in one solve (I + II)
  double time_limit_s = 600.0;           // wall-clock limit of one solve
  // Polled with the time limit (before every Newton iteration and during every Hessian
  // assembly, once per LMI term): returning true ends the solve as soon as it can, with
  // Status::Interrupted (a front end's Ctrl-C). Empty: never. Not a config key.
  std::function<bool()> interrupted;
};

// One centring of the path, for an iteration table.
struct Progress {
  int phase = 2;           // 1: finding a strictly feasible point, 2: minimising cᵀx
  int centering = 0;       // outer (barrier-parameter) step
  double t = 0;            // barrier parameter
  double objective = 0;    // cᵀx (phase 2) or the infeasibility s (phase 1)
  double gap = 0;          // bound on objective − optimum at this point
  int newton = 0;          // Newton iterations in this centring
  double lambda2 = 0;      // Newton decrement² at its end
  double elapsed_s = 0;
  // true: one Newton iteration inside centring `centering` (newton = its index, lambda2
  // its decrement²; objective and gap NaN); false: the centring has ended
  bool newton_step = false;
  // true: a Newton iteration's Hessian is being assembled (reported once per LMI term, so
  // that a problem whose one iteration takes minutes still shows life; only phase, t and
  // elapsed_s are set)
  bool assembling = false;
};
using ProgressObserver = std::function<void(const Progress&)>;

struct Solution {
  Eigen::VectorXd x;
  Status status = Status::NotRun;
  std::string detail;            // human-readable reason for a non-Solved status
  int newton_total = 0, newton_phase1 = 0, centerings = 0;
  double t = 0;
  double objective = 0;          // cᵀx
  double gap = 0;                // certified bound on cᵀx − p* (docs/maths.md (42))
  double relative_gap = 0;       // gap/|cᵀx|
  // The centred points of phase II, oldest first (the last is x): their dual points lie
  // further inside the cone, for the verified bracket (dual_bound.hpp).
  std::vector<Eigen::VectorXd> centred_path;
  // Phase I's centred points (x, s) of its last run, oldest first: when it ends
  // Infeasible, the last is the final point, for the verified certificate of
  // infeasibility (dual_bound.hpp verified_infeasibility).
  std::vector<Eigen::VectorXd> phase1_path;
  // The point lies on the ball ‖x‖ < ρ_b (‖x‖ ≥ ρ_b/2), which may be what bounds it: an
  // Infeasible phase I may find a strictly feasible point in a wider ball, a Solved or
  // StoppedShort solve a better objective (docs/maths.md §4.3, §5.5).
  bool ball_bound = false;
  double feasibility_radius = 0;  // ρ_b of the ball this solution was found in
  double elapsed_s = 0;
};

// x0: optional starting point (size 0 = zero vector).
Solution minimize_linear(const lmi::LmiProblem& lmi, const Eigen::VectorXd& c, const Options& options,
                         const Eigen::VectorXd& x0 = Eigen::VectorXd(),
                         const ProgressObserver& observer = nullptr);

// The largest feasibility radius: beyond ~1e16 the ball's barrier term −log(ρ² − ‖x‖²) is
// lost in the round-off of ‖x‖² (docs/maths.md §4.3).
constexpr double kMaxFeasibilityRadius = 1e16;
// Each retry of minimize_in_wider_balls multiplies the feasibility radius by this factor.
constexpr double kWiderBallFactor = 1e4;

// Which outcomes of minimize_linear minimize_in_wider_balls runs again in a wider ball.
// Always: an outcome bounded by the ball (Solution::ball_bound) and a failure on round-off.
enum class WiderBallsWhen {
  Failed,               // those only
  FailedOrStoppedShort  // those, and a point short of the gap goal (StoppedShort)
};

// minimize_linear, run again with the feasibility radius (options.feasibility_radius)
// kWiderBallFactor times wider, up to max_radius, while its outcome is one
// `when` names; options.time_limit_s covers every attempt. Returns the best point any
// attempt reached (Solved first, then the smallest objective) — a point is never
// discarded — else the last attempt (docs/maths.md §4.3).
Solution minimize_in_wider_balls(const lmi::LmiProblem& lmi, const Eigen::VectorXd& c, const Options& options,
                                 WiderBallsWhen when, const ProgressObserver& observer = nullptr,
                                 double max_radius = kMaxFeasibilityRadius);

// The version of the Newton engine (Ipopt) the solver was built with, for provenance.
const char* newton_engine_version();

}  // namespace hinf::sdp
