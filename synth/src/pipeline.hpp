// The steps every synthesis pipeline shares (Theorem 1, synthesize.cpp; the observer form,
// observer_synthesis.cpp): internal to hinf_synth.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "hinf/lmi/lmi_problem.hpp"
#include "hinf/models/plant.hpp"
#include "hinf/sdp/path_following.hpp"
#include "hinf/sdp/time_model.hpp"
#include "hinf/synth/plant_scaling.hpp"
#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

// A number in messages: 10 significant digits.
std::string fmt(double v);

// The relative gap to which a γ back-off (docs/maths.md §6, the filters' and the
// controller's (149a)) maximises its LMI margin: the margin only has to be near its maximum
// (a well-centred point, not a digit count). At the solver's 1e-7 a margin of ~1e-6 would
// ask for an absolute gap of 1e-13, below round-off.
inline constexpr double kBackoffRelativeGap = 1e-3;

// The solver's memory model (sdp/memory_model.hpp) for this LMI, MiB: p variables plus
// the two of phase I.
double estimated_solve_mib(const lmi::LmiProblem& lmi);
// The solver's time model (sdp/time_model.hpp) for this LMI (p variables plus phase I's two).
sdp::TimeEstimate estimated_solve_time(const lmi::LmiProblem& lmi);

// Refuses (Error(InvalidInput) naming max_memory_mb), before anything of its size is
// allocated, an SDP whose solve the solver's memory model puts above solver.max_memory_mb.
void require_memory(const lmi::LmiProblem& lmi, const Settings& settings, const char* what);

// The exit code of a solve that did not end Solved.
ErrorCode error_code_for(sdp::Status status);

// The solver's progress tagged with the SDP it belongs to (null stays null).
sdp::ProgressObserver staged(const IterationObserver& observer, SolveStage stage);

// Phase I's verdict as a theorem (docs/maths.md (118)): Infeasible only with a verified
// dual certificate; otherwise a numerical failure reporting the smallest violation.
Error infeasibility_verdict(const lmi::LmiProblem& lmi, const sdp::Solution& sol,
                            const std::vector<lmi::SparseEntry>& basis_error, const Settings& settings,
                            const std::string& what, const std::string& hint);

// What an infeasible LMI means when F is block-diagonal (docs/maths.md §23): one multiplier
// per block is a sufficient condition only, so its infeasibility proves no more than that.
std::string structured_infeasible_hint();

// Minimise g subject to `lmi` (Corollary 1 (21), or (124)); throws with the solver's reason,
// or phase I's verdict, if it does not end Solved. `what` names the LMI in messages;
// `failure_hint` is added to a numerical failure (not to a certified infeasibility).
sdp::Solution solve_min_gamma(const lmi::LmiProblem& lmi, lmi::VarId g, const std::vector<lmi::SparseEntry>& basis_error,
                              const Settings& settings, const IterationObserver& observer, const std::string& what,
                              const std::string& infeasible_hint, const std::string& failure_hint = "");

// The γ back-off solve (docs/maths.md §6): minimise `margin` of an LMI with g fixed.
sdp::Solution solve_backoff(const lmi::LmiProblem& lmi, lmi::VarId margin, double gamma2_backoff,
                            const Settings& settings, const IterationObserver& observer);

// The γ back-off (docs/maths.md §6), when settings.gamma_backoff > 0: the problem
// build(γ_b²) (an LMI with a `margin` variable and g fixed at γ_b² = (1 + b)²·γ*²) solved
// for its largest margin, its work added to `info`. Empty when the back-off is off.
template <class Problem>
struct Backoff {
  Problem problem;
  sdp::Solution solution;
  double gamma_squared = 0;
};
template <class Problem, class Build>
std::optional<Backoff<Problem>> solve_gamma_backoff(const sdp::Solution& sol, Build&& build, const Settings& settings,
                                                   const IterationObserver& observer, SolverInfo& info) {
  if (!(settings.gamma_backoff > 0)) return std::nullopt;
  Backoff<Problem> b;
  b.gamma_squared = sol.objective * (1 + settings.gamma_backoff) * (1 + settings.gamma_backoff);
  b.problem = build(b.gamma_squared);
  b.solution = solve_backoff(b.problem.lmi, b.problem.margin, b.gamma_squared, settings, observer);
  info.newton_iterations += b.solution.newton_total;
  info.time_s += b.solution.elapsed_s;
  return b;
}

// Checks 2–4 of the certificate (docs/maths.md §7.2–§7.4) at γ, on the error system of the
// filter's form (certify::error_system); plant, filter and γ in the scaled units. With F
// block-diagonal, `multipliers` (the solver's, one per block; may be empty) start check 4's
// search over the blocks' weights: a witness the certified norm checks, never a verdict (§23).
Certificate certify_checks(const Plant& plant, const Filter& filter, double gamma, const Settings& settings,
                           const Eigen::VectorXd& multipliers = Eigen::VectorXd());

// Checks 1–4 of the certificate at a returned point: check 1 on `dense_lmi` (assembled by
// certify/, never by the solver's data), checks 2–4 on res.filter (`multipliers`: the
// point's, as in certify_checks); fills res.gamma, res.gamma_squared and res.certificate.
void certify_at_point(const Plant& plant, const Eigen::MatrixXd& dense_lmi, double g, const Settings& settings,
                      const Eigen::VectorXd& multipliers, SynthesisResult& res);

// The observer-form pipeline on the scaled plant (observer_synthesis.cpp, docs/maths.md §18).
SynthesisResult synthesize_observer(const Plant& plant, const PlantScaling& sc, const Settings& settings,
                                    const IterationObserver& observer);

// The certificate's numbers in the user's units (docs/maths.md (112)).
Certificate in_user_units(Certificate c, const PlantScaling& s, const Filter& user);

// Why a certificate failed, check by check.
std::string failed_checks(const Certificate& cert, double gamma);

// The optimality bracket (docs/maths.md §5.9) of `lmi` minimising g, in the user's units.
void record_bracket(const lmi::LmiProblem& lmi, lmi::VarId g, const std::vector<lmi::SparseEntry>& basis_error,
                    const sdp::Solution& sol, const Settings& settings, double f, SolverInfo& info);

// What the solve did, for the gains file and -v.
SolverInfo solver_info(const sdp::Solution& sol, const lmi::LmiProblem& lmi, const PlantScaling& sc,
                       const Settings& settings);

}  // namespace hinf::synth
