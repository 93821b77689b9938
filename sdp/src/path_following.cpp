// Path following of the log-det barrier (docs/maths.md §5): the solver loop's state in
// one class, PathFollower, with typed phases and engines and every tolerance a named
// constant below.
#include "hinf/sdp/path_following.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "damped_newton.hpp"
#include "ipopt_centering.hpp"
#include "log_det_barrier.hpp"

namespace hinf::sdp {

namespace {

using Eigen::VectorXd;

// Phase I: ball radius cap and the weight η of the objective in s + η·cᵀx (a small
// weight keeps the phase-I centre from drifting to huge objective values).
constexpr double kPhase1Radius = 1e8;
constexpr double kPhase1Weight = 1e-3;
// A point this far out in its ball (‖x‖ ≥ this·ρ) is the ball's: phase I's smallest s, or
// phase II's optimum, is then taken on the sphere, and a wider ball may hold a better one.
// Phase I is then run again in a ball kWiderBallFactor times wider, up to ρ_b (docs/maths.md
// §5.5); phase II's caller may widen ρ_b (minimize_in_wider_balls, §4.3).
constexpr double kBallBoundFraction = 0.5;
// Phase I without the objective penalty ends as infeasible once s − gap > 0 and the gap
// is within this fraction of s: a point that close to its centre gives a tight,
// verifiable dual certificate (docs/maths.md (118)); the first s − gap > 0 alone is often
// too poorly centred.
constexpr double kInfeasibleGapFraction = 1e-3;
// When a late centring fails on round-off, the last centred point is returned at once if
// its gap is within this many relative_gap_tol; above, shorter steps in t are retried.
// Measured (random n = 16): 10 → 157 Newton iterations ending at a relative gap of
// 2.7e-6 after retries around the floor, 100 → 89 iterations at 5.8e-6 (γ² 4.5e-7 and
// 9.2e-7 above CSDP's); the paper configs never get there.
constexpr double kAcceptAtOnce = 100;
// Shorter steps in t (μ ← √μ from the last centred point) tried after a failed centring.
constexpr int kMaxRetries = 4;
// After the retries, the last centred point is still accepted if its relative gap is
// within max(kAcceptAfterRetries·tol, kAcceptAfterRetriesFloor); the gap is reported.
constexpr double kAcceptAfterRetries = 100;
constexpr double kAcceptAfterRetriesFloor = 1e-5;
// After a centring that stalled on round-off with a gap already within this many tol, the
// next one is at or past the floor: it gets give_up_iterations, not a full budget
// (measured: random n = 10 67 → 61 Newton iterations, same final gap). Not above 10·tol:
// a full budget there still reaches 1e-6 on small random plants (test_solver.cpp's
// GapBracketAndCertificate).
constexpr double kShortBudgetWithin = 10;
// Next t: μ·t, but no further than the tolerance needs (this safety factor on the ratio
// gap/goal), and at least this growth: overshooting only makes the last centring harder
// (its Hessian's condition grows like t²).
constexpr double kGoalSafety = 1.5;
constexpr double kMinGrowth = 2.0;
// The first centring of a phase starts far from the centre (at x0, or at phase I's last
// point near the boundary): Newton's damped stage, which lowers the barrier by at least a
// constant ω(λ) = λ − ln(1 + λ) per step (Nesterov 2004, §4.1), may need more than max_newton_per_centering
// steps there. It gets this many times that budget (COMPleib's HE4: phase I's first
// centring needs 60-120 steps; later centrings start close to the centre and need 5-20).
constexpr int kFirstCentringBudgetFactor = 4;
// Halvings of the predictor step tried to keep it inside the domain.
constexpr int kPredictorHalvings = 40;
// Initial t: never below this fraction of ν/|cᵀx₀|.
constexpr double kInitialTFraction = 1e-3;
// Floors of |objective| in relative quantities (an objective of 0 is possible).
constexpr double kObjectiveFloor = 1e-12;
// The scale of an objective: the callers equilibrate their LMIs (docs/maths.md §4.4), so γ
// or γ² is of order 1 unless the problem makes it large; a wider ball's point that lowers
// the objective by less than relative_gap_tol·max(|objective|, this) is the same optimum,
// further out (γ* = 0 approached only at infinity: 1e-8 in one ball, 1e-12 in the next).
constexpr double kObjectiveScale = 1;
constexpr double kInitialObjectiveFloor = 1e-8;

using Clock = std::chrono::steady_clock;
// Time limits are kept below this (s, ~30 years) so that start + limit cannot overflow.
constexpr double kMaxTimeLimit = 1e9;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

enum class Phase { FindFeasible = 1, Minimise = 2 };
// Which Newton engine centres: Ipopt on the explicit Hessian, or damped Newton on the QR
// step once the explicit Hessian's round-off has reached its smallest eigenvalues.
enum class Engine { Ipopt, QrNewton };
// How a centring that did not centre is handled.
enum class Recovery { Retry, AcceptLastCentred, Fail };

// Gap bound at a point with Newton decrement λ < 1 (ν-self-concordant barrier),
// docs/maths.md (42):   cᵀx − c* ≤ (ν + (λ + √ν)·λ/(1 − λ)) / t,
// from cᵀx*(t) − c* ≤ ν/t, ‖x − x*(t)‖ₓ ≤ λ/(1 − λ) and t‖c‖*ₓ ≤ λ + √ν
// (Nesterov, Introductory Lectures on Convex Optimization, 2004, ch. 4).
double gap_bound(double nu, double lambda2, double t) {
  const double lam = std::sqrt(lambda2);
  return lam < 1 ? (nu + (lam + std::sqrt(nu)) * lam / (1 - lam)) / t : INFINITY;
}

// The state of one barrier's path (phase I or phase II).
struct PathState {
  double t = 0;
  double growth = 0;
  int retries = 0;
  Engine engine = Engine::Ipopt;
  bool have_centred = false;
  bool last_stalled = false;
  bool last_gap_accurate = false;  // last_gap has λ² from the QR Newton step
  VectorXd last_centred;
  double last_gap = 0, last_t = 0;
};

class PathFollower {
 public:
  PathFollower(const lmi::LmiProblem& lmi, const VectorXd& c, const Options& options,
               const ProgressObserver& observer)
      : lmi_(lmi), c_(c), opt_(options), observer_(observer), start_(Clock::now()),
        n_(lmi.num_params()), nu_(lmi.order() + 1.0) {}

  Solution solve(const VectorXd& x0);

 private:
  bool find_feasible(VectorXd& x);
  bool find_feasible_in_ball(VectorXd& x, double lmax, double r1);
  // Runs one barrier along its central path from z; true when it ended as it should
  // (phase I: a strictly feasible point; phase II: the gap goal). z is the final point.
  bool follow(LogDetBarrier& b, VectorXd& z, Phase phase);
  // Ends phase II at the last centred point (z), its gap the solution's: `why` the end game
  // stopped there. StoppedShort if that gap is above the tolerance.
  bool accept_last_centred(const LogDetBarrier& b, VectorXd& z, const std::string& why);
  double initial_t(LogDetBarrier& b, const VectorXd& z) const;
  CenteringOptions centering_options(const LogDetBarrier& b, Phase phase, int centring) const;
  std::function<void()> heartbeat(Phase phase) const;
  CenteringResult centre(LogDetBarrier& b, const VectorXd& z, Phase phase, const CenteringOptions& co);
  Recovery recover(LogDetBarrier& b, Phase phase);
  double accurate_gap(LogDetBarrier& b, const VectorXd& z, double t) const;
  double last_relative_gap(const LogDetBarrier& b) const;
  void predict(LogDetBarrier& b, VectorXd& z, double t_new) const;
  double next_t(Phase phase, double gap, double gap_goal) const;
  bool out_of_budget();
  double remaining() const { return opt_.time_limit_s - seconds_since(start_); }
  // The instant the time limit ends, for the barriers' Hessian assemblies (kMaxTimeLimit:
  // a limit beyond it, e.g. 1e300 s, is no limit and must not overflow the clock).
  Clock::time_point deadline() const {
    return start_ + std::chrono::duration_cast<Clock::duration>(
                        std::chrono::duration<double>(std::min(opt_.time_limit_s, kMaxTimeLimit)));
  }

  const lmi::LmiProblem& lmi_;
  const VectorXd& c_;
  const Options& opt_;
  const ProgressObserver& observer_;
  const Clock::time_point start_;
  const int n_;
  const double nu_;  // barrier parameter: log-det of order N plus the ball
  double phase1_weight_ = 0;
  IpoptCentering ipopt_;
  PathState s_;
  Solution sol_;
  bool stopped_short_ = false;  // phase II ended at a point whose gap is above the tolerance
};

bool PathFollower::out_of_budget() {
  if (sol_.newton_total >= opt_.max_iterations) {
    sol_.status = Status::MaxIterations;
    sol_.detail = "iteration limit (" + std::to_string(opt_.max_iterations) + ") reached";
    return true;
  }
  if (opt_.interrupted && opt_.interrupted()) {
    sol_.status = Status::Interrupted;
    sol_.detail = "interrupted by the caller";
    return true;
  }
  if (remaining() <= 0) {
    sol_.status = Status::TimeLimit;
    sol_.detail = "time limit (" + std::to_string(opt_.time_limit_s) + " s) reached";
    return true;
  }
  return false;
}

// argmin_t ‖t·c + ∇φ‖_{H⁻¹} (Boyd & Vandenberghe §11.3.1), kept above a floor.
double PathFollower::initial_t(LogDetBarrier& b, const VectorXd& z) const {
  const VectorXd cz = b.objective_gradient();
  b.set_t(0.0);
  VectorXd gphi, dz;
  double t = 0;
  if (b.gradient(z, gphi) && b.path_tangent(z, dz)) {
    const double chc = -cz.dot(dz);    // cᵀH⁻¹c
    const double chg = -gphi.dot(dz);  // cᵀH⁻¹∇φ
    if (chc > 0) t = -chg / chc;
  }
  const double obj0 = std::max(std::abs(b.linear_objective(z)), kInitialObjectiveFloor);
  if (!(t > 0) || !std::isfinite(t)) t = nu_ / obj0;
  return std::max(t, kInitialTFraction * nu_ / obj0);
}

// The gap bound at z for barrier parameter t with λ² from the QR Newton step.
double PathFollower::accurate_gap(LogDetBarrier& b, const VectorXd& z, double t) const {
  const double t_now = b.t();
  b.set_t(t);
  VectorXd d;
  double l2 = INFINITY;
  const bool ok = b.accurate_newton(z, d, l2);
  b.set_t(t_now);
  return ok ? gap_bound(nu_, l2, t) : INFINITY;
}

// The last centred gap, relative to |objective| there.
double PathFollower::last_relative_gap(const LogDetBarrier& b) const {
  return s_.last_gap / std::max(std::abs(b.linear_objective(s_.last_centred)), kObjectiveFloor);
}

// The observer's report that a Hessian is being assembled (none without an observer).
std::function<void()> PathFollower::heartbeat(Phase phase) const {
  if (!observer_) return nullptr;
  return [this, phase] {
    Progress p;
    p.phase = static_cast<int>(phase);
    p.t = s_.t;
    p.elapsed_s = seconds_since(start_);
    p.assembling = true;
    observer_(p);
  };
}

CenteringOptions PathFollower::centering_options(const LogDetBarrier& b, Phase phase, int centring) const {
  CenteringOptions co;
  if (observer_) {  // every Newton iteration, so that a large problem shows progress at once
    co.on_newton_step = [this, phase, centring](int newton, double lambda2) {
      Progress p{static_cast<int>(phase), centring, s_.t, NAN, NAN, newton, lambda2, seconds_since(start_)};
      p.newton_step = true;
      observer_(p);
    };
  }
  const int budget = (centring == 0 ? kFirstCentringBudgetFactor : 1) * opt_.max_newton_per_centering;
  co.max_iterations = std::min(budget, std::max(1, opt_.max_iterations - sol_.newton_total));
  if (s_.last_stalled && phase == Phase::Minimise &&
      last_relative_gap(b) <= kShortBudgetWithin * opt_.relative_gap_tol)
    co.max_iterations = std::min(co.max_iterations, co.give_up_iterations);
  co.max_seconds = remaining();
  co.interrupted = opt_.interrupted;
  co.phase1_stop_negative = (phase == Phase::FindFeasible);
  co.stop_on_inexact_newton = (phase == Phase::Minimise);
  return co;
}

// One centring. In phase II, once Ipopt's steps stop being Newton steps, or it stalls or
// fails, the explicit Hessian's round-off (ε·‖H‖, ‖H‖ ~ t²) has reached its smallest
// eigenvalues: this centring is finished, and all later ones are done, by the QR Newton
// step (damped_newton.hpp).
CenteringResult PathFollower::centre(LogDetBarrier& b, const VectorXd& z, Phase phase,
                                     const CenteringOptions& co) {
  if (phase == Phase::Minimise && s_.engine == Engine::QrNewton) return damped_newton_centre(b, z, co);
  CenteringResult r = ipopt_.run(b, z, co);
  // Phase II: also when Ipopt's steps have stopped being Newton steps or it stalled. Phase
  // I: only when Ipopt failed outright (a thin feasible set near the boundary of
  // feasibility, where the explicit Hessian's round-off stops it early).
  const bool failed = !r.centred && !r.stopped_early;
  if (phase == Phase::Minimise ? !(r.inexact || r.stalled || failed) : !failed) return r;
  CenteringOptions cq = co;
  cq.max_iterations = std::max(1, co.max_iterations - r.iterations);
  const CenteringResult q = damped_newton_centre(b, b.inside(r.z) ? r.z : z, cq);
  if (q.centred) {
    const int ipopt_iterations = r.iterations;
    r = q;
    r.iterations += ipopt_iterations;
    s_.engine = Engine::QrNewton;
  } else {
    r.iterations += q.iterations;  // its steps were taken, and count, even if not kept
  }
  return r;
}

// A centring that failed (late in phase II: round-off). The last centred point is still a
// valid answer with its own (larger) gap, reported as achieved: taken at once if that gap
// is within kAcceptAtOnce·tol; otherwise the step in t is shortened (from the last centred
// point, up to kMaxRetries times) and only then is a gap up to
// max(kAcceptAfterRetries·tol, kAcceptAfterRetriesFloor) accepted.
Recovery PathFollower::recover(LogDetBarrier& b, Phase phase) {
  const bool minimise = phase == Phase::Minimise;
  const bool close = minimise && s_.have_centred &&
                     last_relative_gap(b) <= kAcceptAtOnce * opt_.relative_gap_tol;
  if (s_.have_centred && !close && s_.retries < kMaxRetries && !out_of_budget()) {
    ++s_.retries;
    s_.growth = std::sqrt(s_.growth);
    return Recovery::Retry;
  }
  if (minimise && s_.have_centred && !s_.last_gap_accurate) {
    s_.last_gap = accurate_gap(b, s_.last_centred, s_.last_t);
    s_.last_gap_accurate = true;
  }
  if (minimise && s_.have_centred &&
      last_relative_gap(b) <= std::max(kAcceptAfterRetries * opt_.relative_gap_tol, kAcceptAfterRetriesFloor))
    return Recovery::AcceptLastCentred;
  return Recovery::Fail;
}

// Three significant digits, for the detail of a point returned short of the tolerance.
std::string three_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

bool PathFollower::accept_last_centred(const LogDetBarrier& b, VectorXd& z, const std::string& why) {
  sol_.gap = s_.last_gap;
  sol_.t = s_.last_t;
  z = s_.last_centred;
  const double relative = last_relative_gap(b);
  stopped_short_ = relative > opt_.relative_gap_tol;
  const std::string gap_text = std::isfinite(relative)
                                   ? "relative gap " + three_digits(relative) + ", above the tolerance " +
                                         three_digits(opt_.relative_gap_tol)
                                   : std::string("its gap not bounded: the accurate Newton step failed there");
  sol_.detail = why + "; returned the last centred point" + (stopped_short_ ? " (" + gap_text + ")" : std::string());
  return true;
}

// Predictor along the central path, kept inside the domain. x*(t) − x* = O(1/t) on the
// central path: extrapolate linearly in 1/t, Δx = (dx/d(1/t))·(1/t_new − 1/t) =
// t·(1 − t/t_new)·dx/dt.
void PathFollower::predict(LogDetBarrier& b, VectorXd& z, double t_new) const {
  VectorXd dz;
  const bool have = s_.engine == Engine::QrNewton ? b.accurate_path_tangent(z, dz) : b.path_tangent(z, dz);
  if (!have) return;
  const double t = s_.t;
  const VectorXd step = (t * (1.0 - t / t_new)) * dz;
  double alpha = 1.0;
  for (int tries = 0; tries < kPredictorHalvings; ++tries, alpha *= 0.5) {
    const VectorXd zt = z + alpha * step;
    if (b.inside(zt)) {
      z = zt;
      return;
    }
  }
}

double PathFollower::next_t(Phase phase, double gap, double gap_goal) const {
  const double t = s_.t;
  if (phase != Phase::Minimise) return s_.growth * t;
  return std::min(s_.growth * t, std::max(kMinGrowth * t, kGoalSafety * t * gap / gap_goal));
}

bool PathFollower::follow(LogDetBarrier& b, VectorXd& z, Phase phase) {
  s_ = PathState();
  s_.growth = opt_.barrier_growth;
  s_.t = initial_t(b, z);
  const bool minimise = phase == Phase::Minimise;
  for (int k = 0;; ++k) {
    b.set_t(s_.t);
    const CenteringResult r = centre(b, z, phase, centering_options(b, phase, k));
    sol_.newton_total += r.iterations;
    if (!minimise) sol_.newton_phase1 += r.iterations;
    ++sol_.centerings;
    z = r.z;
    const double obj = minimise ? b.linear_objective(z) : z(n_);
    const double gap = gap_bound(nu_, r.lambda2, s_.t);
    // λ² of the QR Newton step is the trustworthy one (the explicit Hessian's may be off
    // late on the path); a gap that ends phase II is always certified with it.
    const bool gap_accurate = minimise && s_.engine == Engine::QrNewton;
    if (observer_)
      observer_({static_cast<int>(phase), k, s_.t, obj, gap, r.iterations, r.lambda2, seconds_since(start_)});
    if (!minimise && (r.stopped_early || obj < 0)) return true;
    if (!r.centred && !r.stopped_early && r.out_of_memory) {  // shorter steps would not need less memory
      sol_.status = Status::OutOfMemory;
      sol_.detail = "in phase " + std::to_string(static_cast<int>(phase)) + " at t = " + std::to_string(s_.t);
      return false;
    }
    if (!r.centred && !r.stopped_early) {
      switch (recover(b, phase)) {
        case Recovery::Retry:
          z = s_.last_centred;
          s_.t = s_.last_t * s_.growth;
          continue;
        case Recovery::AcceptLastCentred:
          return accept_last_centred(b, z, "final centring stopped by round-off");
        case Recovery::Fail: {
          if (out_of_budget()) return false;
          const std::string failed = "centring failed in phase " + std::to_string(static_cast<int>(phase)) +
                                     " at t = " + std::to_string(s_.t) + " (" +
                                     (s_.engine == Engine::QrNewton ? "QR Newton: " : "Ipopt: ") + r.status + ")";
          if (minimise && s_.have_centred) return accept_last_centred(b, z, failed);  // the best point, kept
          sol_.status = Status::NumericalError;
          sol_.detail = failed;
          return false;
        }
      }
    }
    if (!minimise) sol_.phase1_path.push_back(z);
    if (!minimise && obj - gap > 0 && (phase1_weight_ > 0 || gap <= kInfeasibleGapFraction * obj)) {
      // s* > 0: under the objective penalty, retry without it at once; without it,
      // infeasible by the gap estimate (s − gap > 0), for the caller to verify
      if (phase1_weight_ > 0) return false;
      sol_.status = Status::Infeasible;
      sol_.detail = "no strictly feasible point: min s = " + std::to_string(obj) + " > 0";
      return false;
    }
    sol_.t = s_.t;
    sol_.gap = gap;
    s_.last_stalled = r.stalled;
    s_.last_centred = z;
    s_.last_gap = gap;
    s_.last_gap_accurate = gap_accurate;
    s_.last_t = s_.t;
    s_.have_centred = true;
    if (minimise) sol_.centred_path.push_back(z.head(n_));
    const double gap_goal = opt_.relative_gap_tol * std::max(std::abs(obj), kObjectiveFloor);
    if (minimise && gap <= gap_goal) {
      if (gap_accurate) return true;
      // certify with the QR step's λ²; if that misses the goal, re-centre at this t with
      // QR Newton steps from here on
      sol_.gap = s_.last_gap = accurate_gap(b, z, s_.t);
      s_.last_gap_accurate = true;
      if (sol_.gap <= gap_goal) return true;
      s_.engine = Engine::QrNewton;
      continue;
    }
    if (out_of_budget()) return false;
    const double t_new = next_t(phase, gap, gap_goal);
    predict(b, z, t_new);
    s_.t = t_new;
  }
}

// Phase I, if x is not already strictly feasible: minimise s + η·cᵀx with
// M(x) + εI ⪯ sI, first with η = kPhase1Weight, then with η = 0; in wider balls while
// its infeasibility is the ball's (docs/maths.md §5.5).
bool PathFollower::find_feasible(VectorXd& x) {
  const int N = lmi_.order();
  Eigen::MatrixXd M = lmi_.evaluate(x);
  M.diagonal().array() += opt_.lmi_margin;
  const double lmax =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M, Eigen::EigenvaluesOnly).eigenvalues()(N - 1);
  if (lmax < 0) return true;
  // A small ball in phase I keeps its analytic centre near x0 instead of at the
  // feasibility radius (which would make phase II start with huge variables).
  const VectorXd x0 = x;
  for (double r1 = std::min(opt_.feasibility_radius, kPhase1Radius);;
       r1 = std::min(r1 * kWiderBallFactor, opt_.feasibility_radius)) {
    sol_.status = Status::NotRun;
    sol_.detail.clear();
    x = x0;
    const bool ok = find_feasible_in_ball(x, lmax, r1);
    sol_.ball_bound = sol_.status == Status::Infeasible && x.norm() >= kBallBoundFraction * r1;
    if (ok || !sol_.ball_bound) return ok;
    if (r1 >= opt_.feasibility_radius) {
      sol_.detail += "; phase I's last point lies on its ball ‖x‖ < " + three_digits(r1) +
                     ": a wider ball may hold a strictly feasible point";
      return false;
    }
    if (out_of_budget()) return false;
  }
}

// Phase I in the ball ‖x‖ < r1 from x (λ_max(M(x) + εI) = lmax): x becomes its last point.
bool PathFollower::find_feasible_in_ball(VectorXd& x, double lmax, double r1) {
  VectorXd z(n_ + 1);
  bool ok = false;
  for (double eta : {kPhase1Weight, 0.0}) {
    phase1_weight_ = eta;
    sol_.phase1_path.clear();
    LogDetBarrier b1(lmi_, c_, opt_.lmi_margin, r1, true, eta);
    b1.set_deadline(deadline(), opt_.interrupted);
    b1.set_heartbeat(heartbeat(Phase::FindFeasible));
    z.head(n_) = x;
    z(n_) = lmax + 1.0;
    ok = follow(b1, z, Phase::FindFeasible);
    if (ok || sol_.status != Status::NotRun) break;
  }
  x = z.head(n_);
  if (!ok && sol_.status == Status::NotRun) {
    sol_.status = Status::NumericalError;
    sol_.detail = "phase I did not find a feasible point";
  }
  return ok;
}

Solution PathFollower::solve(const VectorXd& x0) {
  VectorXd x = x0.size() == n_ ? x0 : VectorXd::Zero(n_);
  sol_.feasibility_radius = opt_.feasibility_radius;
  if (!find_feasible(x)) {
    sol_.x = x;
    sol_.elapsed_s = seconds_since(start_);
    return sol_;
  }
  LogDetBarrier b2(lmi_, c_, opt_.lmi_margin, opt_.feasibility_radius, false);
  b2.set_deadline(deadline(), opt_.interrupted);
  b2.set_heartbeat(heartbeat(Phase::Minimise));
  const bool ok = follow(b2, x, Phase::Minimise);
  sol_.x = x;
  sol_.objective = c_.dot(x);
  sol_.elapsed_s = seconds_since(start_);
  if (!ok) {
    if (sol_.status == Status::NotRun) sol_.status = Status::NumericalError;
    return sol_;
  }
  sol_.status = stopped_short_ ? Status::StoppedShort : Status::Solved;
  // the ball, not the LMI, may bound the objective there (docs/maths.md §4.3)
  sol_.ball_bound = x.norm() >= kBallBoundFraction * opt_.feasibility_radius;
  sol_.relative_gap = sol_.gap / std::max(std::abs(sol_.objective), 1e-300);
  return sol_;
}

}  // namespace

Solution minimize_linear(const lmi::LmiProblem& lmi, const VectorXd& c, const Options& options,
                         const VectorXd& x0, const ProgressObserver& observer) {
  PathFollower follower(lmi, c, options, observer);
  return follower.solve(x0);
}

Solution minimize_in_wider_balls(const lmi::LmiProblem& lmi, const VectorXd& c, const Options& options,
                                 WiderBallsWhen when, const ProgressObserver& observer, double max_radius) {
  const Clock::time_point start = Clock::now();
  Options o = options;
  Solution sol = minimize_linear(lmi, c, o, VectorXd(), observer);
  std::optional<Solution> best;
  // a wider ball's point replaces the best only if it is Solved where the best is not, or
  // lowers the objective by more than the tolerance (else it is the same optimum, further out)
  bool replaced = false;
  const auto keep_best = [&] {
    replaced = false;
    if (!has_point(sol.status)) return;
    const double noise = options.relative_gap_tol * (best ? std::max(std::abs(best->objective), kObjectiveScale) : 0);
    if (!best || (sol.status == Status::Solved && best->status != Status::Solved) ||
        sol.objective < best->objective - noise) {
      best = sol;
      replaced = true;
    }
  };
  keep_best();
  // a point on the ball is tried in a wider one until a wider ball stops improving it
  const auto worth_a_wider_ball = [&] {
    return sol.status == Status::NumericalError ||
           (when == WiderBallsWhen::FailedOrStoppedShort && sol.status == Status::StoppedShort) ||
           (sol.ball_bound && (sol.status == Status::Infeasible || replaced));
  };
  max_radius = std::min(max_radius, kMaxFeasibilityRadius);
  while (worth_a_wider_ball() && o.feasibility_radius < max_radius) {
    o.feasibility_radius = std::min(o.feasibility_radius * kWiderBallFactor, max_radius);
    o.time_limit_s = options.time_limit_s - seconds_since(start);
    if (o.time_limit_s <= 0) break;
    sol = minimize_linear(lmi, c, o, VectorXd(), observer);
    keep_best();
  }
  return best ? *best : sol;
}

}  // namespace hinf::sdp
