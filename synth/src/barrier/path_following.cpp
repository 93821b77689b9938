#include "barrier/path_following.hpp"

#include <chrono>
#include <cmath>

#include "barrier/damped_newton.hpp"
#include "barrier/ipopt_centering.hpp"
#include "barrier/log_det_barrier.hpp"

namespace hinf::barrier {

namespace {

// Phase I: ball radius cap and the weight η of the objective in s + η·cᵀx.
constexpr double kPhase1Radius = 1e8;
constexpr double kPhase1Weight = 1e-3;
// When a late centring fails on round-off, the last centred point is returned at once if
// its gap is within this many relative_gap_tol; above, shorter steps in t are retried.
// Measured (random n = 16): 10 → 157 Newton iterations ending at a relative gap of
// 2.7e-6 after retries around the floor, 100 → 89 iterations at 5.8e-6 (γ² 4.5e-7 and
// 9.2e-7 above CSDP's); the paper configs never get there.
constexpr double kAcceptAtOnce = 100;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

SdpSolution minimize_linear(const lmi::LmiProblem& lmi, const Eigen::VectorXd& c,
                            const Settings& settings, const Eigen::VectorXd& x0_in,
                            const IterationObserver& observer) {
  const auto start = Clock::now();
  const int n = lmi.num_params();
  const int N = lmi.order();
  const double nu = N + 1.0;  // barrier parameter: log-det of order N plus the ball
  SdpSolution sol;
  IpoptCentering ipopt;
  Eigen::VectorXd x0 = x0_in.size() == n ? x0_in : Eigen::VectorXd::Zero(n);

  double phase1_weight = 0;
  auto remaining = [&] { return settings.time_limit_s - seconds_since(start); };
  auto out_of_budget = [&](SdpSolution& s) {
    if (s.newton_total >= settings.max_iterations) {
      s.status = SolverStatus::MaxIterations;
      s.detail = "iteration limit (" + std::to_string(settings.max_iterations) + ") reached";
      return true;
    }
    if (remaining() <= 0) {
      s.status = SolverStatus::TimeLimit;
      s.detail = "time limit (" + std::to_string(settings.time_limit_s) + " s) reached";
      return true;
    }
    return false;
  };

  // Gap bound at a point with Newton decrement λ < 1 (ν-self-concordant barrier):
  //   cᵀx − c* ≤ (ν + (λ + √ν)·λ/(1 − λ)) / t,
  // from cᵀx*(t) − c* ≤ ν/t, ‖x − x*(t)‖ₓ ≤ λ/(1 − λ) and t‖c‖*ₓ ≤ λ + √ν
  // (Nesterov, Introductory Lectures on Convex Optimization, 2004, ch. 4: the local-norm
  // distance to the minimiser of a self-concordant function, and ‖∇F‖*ₓ ≤ √ν).
  auto gap_bound = [nu](double lambda2, double t) {
    const double lam = std::sqrt(lambda2);
    return lam < 1 ? (nu + (lam + std::sqrt(nu)) * lam / (1 - lam)) / t : INFINITY;
  };

  // Runs one barrier (phase 1 or 2) along its central path. Returns the final z.
  auto follow = [&](LogDetBarrier& b, Eigen::VectorXd z, int phase, bool& ok) -> Eigen::VectorXd {
    ok = false;
    // initial t (Boyd & Vandenberghe §11.3.1): argmin_t ‖t·c + ∇φ‖_{H⁻¹}
    const Eigen::VectorXd cz = b.objective_gradient();
    b.set_t(0.0);
    Eigen::VectorXd gphi, dz;
    double t = 0;
    if (b.gradient(z, gphi) && b.path_tangent(z, dz)) {
      const double chc = -cz.dot(dz);       // cᵀH⁻¹c
      const double chg = -gphi.dot(dz);     // cᵀH⁻¹∇φ
      if (chc > 0) t = -chg / chc;
    }
    const double obj0 = std::abs(b.linear_objective(z));
    Eigen::VectorXd last_centred;
    double last_gap = 0, last_t = 0;
    double growth = settings.barrier_growth;
    int retries = 0;
    bool have_centred = false;
    bool last_stalled = false;
    bool qr_mode = false;  // phase II past the explicit Hessian's round-off: QR Newton steps
    bool last_gap_accurate = false;
    // The gap bound at z for barrier parameter tz with λ² from the QR Newton step.
    auto accurate_gap = [&](const Eigen::VectorXd& zc, double tz) {
      const double t_now = b.t();
      b.set_t(tz);
      Eigen::VectorXd d;
      double l2 = INFINITY;
      const bool ok_qr = b.accurate_newton(zc, d, l2);
      b.set_t(t_now);
      return ok_qr ? gap_bound(l2, tz) : INFINITY;
    };
    // The last centred gap, relative to |objective| there (phase II's tests below).
    auto last_relative_gap = [&] {
      return last_gap / std::max(std::abs(b.linear_objective(last_centred)), 1e-12);
    };
    if (!(t > 0) || !std::isfinite(t)) t = nu / std::max(obj0, 1e-8);
    t = std::max(t, 1e-3 * nu / std::max(obj0, 1e-8));
    for (int k = 0;; ++k) {
      b.set_t(t);
      CenteringOptions co;
      co.max_iterations = std::min(settings.max_newton_per_centering,
                                   std::max(1, settings.max_iterations - sol.newton_total));
      // After a centring that stalled on round-off with a gap already within 10·tol, the
      // next one is at or past the floor: it gets give_up_iterations, not a full budget
      // (measured: random n = 10 67 → 61 Newton iterations, same final gap). Not above
      // 10·tol: a full budget there still reaches 1e-6 on small random plants
      // (test_solver's GapBracketAndCertificate).
      if (last_stalled && phase == 2 && last_relative_gap() <= 10 * settings.relative_gap_tol)
        co.max_iterations = std::min(co.max_iterations, co.give_up_iterations);
      co.max_cpu_time = remaining();
      co.phase1_stop_negative = (phase == 1);
      co.stop_on_inexact_newton = (phase == 2);
      CenteringResult r;
      if (phase == 2 && qr_mode) {
        r = damped_newton_centre(b, z, co);
      } else {
        r = ipopt.run(b, z, co);
        // Ipopt's steps stopped being Newton steps, or it stalled or failed, in phase II:
        // the explicit Hessian's round-off (ε·‖H‖, ‖H‖ ~ t²) has reached its smallest
        // eigenvalues. Finish this centring, and do all later ones, with the QR Newton
        // step (damped_newton.hpp).
        if (phase == 2 && (r.inexact || r.stalled || !r.centred)) {
          CenteringOptions cq = co;
          cq.max_iterations = std::max(1, co.max_iterations - r.iterations);
          const CenteringResult q = damped_newton_centre(b, b.inside(r.z) ? r.z : z, cq);
          if (q.centred) {
            const int ipopt_iterations = r.iterations;
            r = q;
            r.iterations += ipopt_iterations;
            qr_mode = true;
          } else {
            r.iterations += q.iterations;  // its steps were taken, and count, even if not kept
          }
        }
      }
      sol.newton_total += r.iterations;
      if (phase == 1) sol.newton_phase1 += r.iterations;
      ++sol.centerings;
      z = r.z;
      const double obj = phase == 1 ? z(n) : b.linear_objective(z);
      const double gap = gap_bound(r.lambda2, t);
      // λ² of the QR Newton step is the trustworthy one (the explicit Hessian's may be off
      // late on the path); a gap that ends phase II is always certified with it.
      const bool gap_accurate = phase == 2 && qr_mode;
      if (observer)
        observer({synth::SolveStage::Synthesis, phase, k, t, obj, gap, r.iterations, r.lambda2, seconds_since(start)});
      if (phase == 1 && (r.stopped_early || obj < 0)) {
        ok = true;
        return z;
      }
      if (!r.centred && !r.stopped_early) {
        // Late in phase II the centring may fail on round-off. The last centred point is
        // still a valid answer with its own (larger) gap, reported as achieved: taken at
        // once if that gap is within kAcceptAtOnce·tol; otherwise the step in t is
        // shortened (from the last centred point, up to 4 times) and only then is a gap up
        // to max(100·tol, 1e-5) accepted.
        const bool close =
            phase == 2 && have_centred && last_relative_gap() <= kAcceptAtOnce * settings.relative_gap_tol;
        const bool retry = have_centred && !close && retries < 4 && !out_of_budget(sol);
        if (retry) {
          ++retries;
          growth = std::sqrt(growth);
          z = last_centred;
          t = last_t * growth;
          continue;
        }
        if (phase == 2 && have_centred && !last_gap_accurate) {
          last_gap = accurate_gap(last_centred, last_t);
          last_gap_accurate = true;
        }
        if (phase == 2 && have_centred &&
            last_relative_gap() <= std::max(100 * settings.relative_gap_tol, 1e-5)) {
          sol.gap = last_gap;
          sol.detail = "final centring stopped by round-off; returned the last centred point";
          ok = true;
          return last_centred;
        }
        if (out_of_budget(sol)) return z;
        sol.status = SolverStatus::NumericalError;
        sol.detail = "centring failed in phase " + std::to_string(phase) + " at t = " +
                     std::to_string(t) + " (" + (qr_mode ? "QR Newton: " : "Ipopt: ") + r.status + ")";
        return z;
      }
      if (phase == 1 && phase1_weight > 0 && obj - gap > 0) {
        return z;  // converged with s > 0 under the objective penalty: retry without it
      }
      if (phase == 1 && obj - gap > 0) {
        // certified: even the dual bound on s* is positive
        sol.status = SolverStatus::Infeasible;
        sol.phase1_s = obj;
        sol.detail = "no strictly feasible point: min s = " + std::to_string(obj) + " > 0";
        return z;
      }
      sol.t = t;
      sol.gap = gap;
      last_stalled = r.stalled;
      last_centred = z;
      last_gap = gap;
      last_gap_accurate = gap_accurate;
      last_t = t;
      have_centred = true;
      const double gap_goal = settings.relative_gap_tol * std::max(std::abs(obj), 1e-12);
      if (phase == 2 && gap <= gap_goal) {
        if (!gap_accurate) {
          // certify with the QR step's λ²; if that misses the goal, re-centre at this t
          // with QR Newton steps from here on
          sol.gap = last_gap = accurate_gap(z, t);
          last_gap_accurate = true;
          if (!(sol.gap <= gap_goal)) {
            qr_mode = true;
            continue;
          }
        }
        ok = true;
        return z;
      }
      if (out_of_budget(sol)) return z;
      // Next t: μ·t, but no further than the tolerance needs (with a 1.5 safety factor) —
      // overshooting only makes the last centring harder (its Hessian's condition grows like t²).
      const double t_new =
          phase == 2 ? std::min(growth * t, std::max(2.0 * t, 1.5 * t * gap / gap_goal)) : growth * t;
      // predictor along the central path, kept inside the domain
      if (qr_mode ? b.accurate_path_tangent(z, dz) : b.path_tangent(z, dz)) {
        double alpha = 1.0;
        // x*(t) − x* = O(1/t) on the central path: extrapolate linearly in 1/t, i.e.
        // Δx = (dx/d(1/t))·(1/t_new − 1/t) = t·(1 − t/t_new)·dx/dt.
        Eigen::VectorXd step = (t * (1.0 - t / t_new)) * dz;
        for (int tries = 0; tries < 40; ++tries, alpha *= 0.5) {
          const Eigen::VectorXd zt = z + alpha * step;
          if (b.inside(zt)) {
            z = zt;
            break;
          }
        }
      }
      t = t_new;
    }
  };

  // ---- phase I --------------------------------------------------------------------
  Eigen::VectorXd x = x0;
  {
    Eigen::MatrixXd M = lmi.evaluate(x);
    M.diagonal().array() += settings.lmi_margin;
    const double lmax = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M, Eigen::EigenvaluesOnly)
                            .eigenvalues()(N - 1);
    if (lmax >= 0) {
      // A small ball in phase I keeps its analytic centre near x0 instead of at the
      // feasibility radius (which would make phase II start with huge variables).
      const double r1 = std::min(settings.feasibility_radius, kPhase1Radius);
      Eigen::VectorXd z(n + 1);
      bool ok = false;
      for (double eta : {kPhase1Weight, 0.0}) {
        phase1_weight = eta;
        LogDetBarrier b1(lmi, c, settings.lmi_margin, r1, true, eta);
        z.head(n) = x;
        z(n) = lmax + 1.0;
        z = follow(b1, z, 1, ok);
        if (ok || sol.status != SolverStatus::NotRun) break;
      }
      sol.phase1_s = z(n);
      if (!ok) {
        if (sol.status == SolverStatus::NotRun) {
          sol.status = SolverStatus::NumericalError;
          sol.detail = "phase I did not find a feasible point";
        }
        sol.x = z.head(n);
        sol.elapsed_s = seconds_since(start);
        return sol;
      }
      x = z.head(n);
    }
  }
  // ---- phase II -------------------------------------------------------------------
  LogDetBarrier b2(lmi, c, settings.lmi_margin, settings.feasibility_radius, false);
  bool ok = false;
  x = follow(b2, x, 2, ok);
  sol.x = x;
  sol.objective = c.dot(x);
  sol.elapsed_s = seconds_since(start);
  if (!ok) {
    if (sol.status == SolverStatus::NotRun) sol.status = SolverStatus::NumericalError;
    return sol;
  }
  sol.status = SolverStatus::Solved;
  sol.relative_gap = sol.gap / std::max(std::abs(sol.objective), 1e-300);
  // Dual point Z = W/t: tr(Z Mᵢ) ≈ −cᵢ; dual objective tr(Z M₀) (margin removed).
  if (b2.inside(x)) {
    Eigen::VectorXd g;
    b2.gradient(x, g);  // makes W current at x
    sol.dual_bound = (b2.W().cwiseProduct(lmi.constant())).sum() / sol.t;
  }
  return sol;
}

}  // namespace hinf::barrier
