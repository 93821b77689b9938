// synthesize_controller, controller_sdpa (controller_synthesis.hpp).
#include "hinf/synth/controller_synthesis.hpp"

#include <limits>
#include <cmath>
#include <complex>
#include <optional>
#include <string>

#include "controller_lmi.hpp"
#include "controller_scaling.hpp"
#include "hinf/certify/controller_certificate.hpp"
#include "hinf/certify/pbh.hpp"
#include "hinf/common/error.hpp"
#include "hinf/lmi/sdpa_format.hpp"
#include "hinf/sdp/dual_bound.hpp"
#include "hinf/sdp/path_following.hpp"
#include "pipeline.hpp"

namespace hinf::synth {

namespace {

// When the γ-optimal point does not give a controller (I − R S numerically singular, or a
// certificate lost to round-off), the back-offs (149a) tried in turn (the γ written says which).
constexpr double kAutomaticBackoffs[] = {1e-7, 1e-5, 1e-3, 1e-2, 5e-2};
// The widest ball the controller LMI is solved in: points further out are a hair nearer γ*
// but so large that I − R S is singular to working precision at every back-off, so no
// controller is recovered from them (docs/maths.md §4.3; measured on the plant
// 1/(s(s − p)): p = 1e5 gives a certified controller from the 1e12 ball, none from 1e16).
constexpr double kMaxControllerRadius = 1e12;
// The balls the controller LMI is solved in again when no controller is recovered from the
// ball of γ*'s point (recover_in_narrower_balls): each this factor narrower than the last,
// down to the narrowest (measured on COMPleib's singular plants: radius 1e4 recovers some,
// 1e2 more, at a γ* a little higher; those whose optimum needs a wider ball, 1e6).
constexpr double kNarrowerBallFactor = 1e2;
constexpr double kNarrowestControllerBall = 1e2;
// A controller certified from the optimum's ball only at a back-off above this, with the
// optimum on its ball (approached only as R and S grow), is compared with the narrower
// balls' (the smallest certified norm kept): the back-off's point of largest margin lies on
// the ball too, and a narrower ball's often recovers at or nearer its optimum (COMPleib's
// AC8: 1e-2 fails and 5e-2 recovers in the 1e8 ball, certified 1.637544504; the 1e4 ball's
// optimum itself recovers, 1.616482682; hinfsyn 1.616762222). The tolerance on γ.
constexpr double kNarrowerBallBackoff = 1e-6;
// The robust design's D-scaling search (docs/maths.md (160a)): decades of d from 1e-6 to
// 1e3, then golden sections within a decade of the best.
constexpr double kLogDLow = -6, kLogDHigh = 3;
constexpr int kGoldenSteps = 8;
// The least ‖T_qp‖∞ of the robust design (160a) is first found to this relative gap only:
// without noise in y that problem is singular, its infimum approached at the end of the path.
constexpr double kLeastChannelNormRelativeGap = 1e-3;

void check_dimensions(const hinf::GeneralisedPlant& P) {
  const int n = P.n();
  const auto need = [](const char* name, const Eigen::MatrixXd& M, int r, int c) {
    if (M.rows() != r || M.cols() != c)
      throw Error(ErrorCode::InvalidInput, std::string("controller.") + name + ": expected " + std::to_string(r) +
                                               "x" + std::to_string(c) + ", got " + std::to_string(M.rows()) + "x" +
                                               std::to_string(M.cols()), name);
    if (!M.allFinite()) throw Error(ErrorCode::InvalidInput, std::string("controller.") + name + ": non-finite entry", name);
  };
  if (n == 0) throw Error(ErrorCode::InvalidInput, "controller.A: empty plant", "A");
  need("A", P.A, n, n);
  need("B1", P.B1, n, P.nw());
  need("B2", P.B2, n, P.nu());
  need("C1", P.C1, P.nz(), n);
  need("C2", P.C2, P.ny(), n);
  need("D11", P.D11, P.nz(), P.nw());
  need("D12", P.D12, P.nz(), P.nu());
  need("D21", P.D21, P.ny(), P.nw());
  if (P.time == hinf::TimeDomain::Discrete && !(P.sample_time > 0))
    throw Error(ErrorCode::InvalidInput, "controller.sample_time: must be positive in discrete time", "sample_time");
}




// The equilibrated plant, the disk in its time unit, and the LMI on them.
struct ScaledControllerLmi {
  ControllerScaling scaling;
  hinf::GeneralisedPlant plant;
  ControllerDesign design;  // the disk in the scaled time unit
  ControllerLmi lmi;
};
ScaledControllerLmi scaled_controller_lmi(const hinf::GeneralisedPlant& P, const ControllerDesign& design) {
  ScaledControllerLmi s;
  s.scaling = choose_controller_scaling(P);
  s.plant = scaled_generalised_plant(P, s.scaling);
  s.design = design;
  if (design.pole_disk_radius && P.time == hinf::TimeDomain::Continuous)
    s.design.pole_disk_radius = *design.pole_disk_radius / s.scaling.time;
  s.lmi = build_controller_lmi(s.plant, s.design);
  return s;
}

// No controller makes the loop stable (with its poles in the disk |λ| < r, if one is asked)
// unless (A, B2) is stabilisable and (A, C2) detectable in that region — and when they are,
// (149)/(150) (with (153)) is feasible for a large enough γ. Checked on the equilibrated plant
// (time unit 1/ω) and confirmed on the user's (a verdict of one coordinate system's rounding
// alone is none), reported in the user's units: Error(Infeasible) naming the mode.
void require_stabilisable_detectable(const hinf::GeneralisedPlant& user, const ControllerDesign& user_design,
                                     const ScaledControllerLmi& S) {
  const hinf::GeneralisedPlant& P = S.plant;
  const double user_disk = user_design.pole_disk_radius.value_or(std::numeric_limits<double>::infinity());
  const bool discrete = P.time == hinf::TimeDomain::Discrete;
  const double disk = S.design.pole_disk_radius.value_or(std::numeric_limits<double>::infinity());
  const double omega = S.scaling.time;
  const std::string region = std::string(discrete ? "|λ| ≥ 1" : "Re λ ≥ 0") +
                             (S.design.pole_disk_radius ? " or outside the pole disk |λ| < " + fmt(disk * omega) : "");
  const std::string goal = S.design.pole_disk_radius ? "stable with its poles in the disk" : "stable";
  const auto text = [omega](std::complex<double> z) {
    z *= omega;
    return fmt(z.real()) + (z.imag() == 0 ? "" : (z.imag() > 0 ? " + " : " - ") + fmt(std::abs(z.imag())) + "i");
  };
  if (const auto m = certify::unseen_unstable_mode(P.A.transpose(), P.B2.transpose(), discrete, disk);
      m && certify::unseen_unstable_mode(user.A.transpose(), user.B2.transpose(), discrete, user_disk))
    throw Error(ErrorCode::Infeasible, "infeasible: (A, B2) is not stabilisable: the mode λ = " + text(m->lambda) + " of A (" +
                                           region + ") is not reached by the control u, so no controller makes the "
                                           "closed loop " + goal + " (PBH test, docs/maths.md (126))");
  if (const auto m = certify::unseen_unstable_mode(P.A, P.C2, discrete, disk);
      m && certify::unseen_unstable_mode(user.A, user.C2, discrete, user_disk))
    throw Error(ErrorCode::Infeasible, "infeasible: (A, C2) is not detectable: the mode λ = " + text(m->lambda) + " of A (" +
                                           region + ") is not seen in the measurement y, so no controller makes the "
                                           "closed loop " + goal + " (PBH test, docs/maths.md (126))");
}
}  // namespace

std::string controller_sdpa(const hinf::GeneralisedPlant& P, const ControllerDesign& design, const std::string& comment) {
  check_dimensions(P);
  const ScaledControllerLmi S = scaled_controller_lmi(P, design);
  return lmi::to_sdpa_sparse(S.lmi.lmi, S.lmi.lmi.cost_of(S.lmi.g),
                             "controller LMI (docs/maths.md " +
                                 std::string(P.time == hinf::TimeDomain::Discrete ? "(150)" : "(149)") + ") " + comment +
                                 "\nvariable " + std::to_string(S.lmi.lmi.variable(S.lmi.g).offset + 1) +
                                 " is the scaled gamma; gamma = it times " + fmt(S.scaling.gamma_factor()) +
                                 " (the equilibration (154))");
}

namespace {

// Minimises γ over an LMI built by build_controller_lmi: the solution, or Error with the
// solver's verdict (`what` names the LMI).
// Whether the LMI is known to be feasible (for a large enough γ): then a phase I that ends
// "infeasible" is a numerical failure (exit 4), never a certificate (exit 3).
enum class KnownFeasible { No, Yes };

sdp::Solution minimize_gamma(const ControllerLmi& C, const Settings& settings, const IterationObserver& observer,
                             const std::string& what, double relative_gap_tol = 0,
                             KnownFeasible known = KnownFeasible::No) {
  sdp::Options options = settings.solver;
  options.relative_gap_tol = std::max(options.relative_gap_tol, relative_gap_tol);
  // γ* can lie far out (a fast unstable pole seen through an integrator: γ* ≈ 2p²), beyond
  // the configured ball: wider balls when phase I finds none in it, the optimum lies on it,
  // or a solve fails; not after stopping short, and not beyond kMaxControllerRadius
  // (docs/maths.md §4.3).
  const sdp::Solution sol =
      sdp::minimize_in_wider_balls(C.lmi, C.lmi.cost_of(C.g), options, sdp::WiderBallsWhen::Failed,
                                   staged(observer, SolveStage::Controller), kMaxControllerRadius);
  if (sol.status == sdp::Status::Infeasible && known == KnownFeasible::Yes)
    throw Error(ErrorCode::NumericalFailure,
                what + ": phase I stopped short of a strictly feasible point (" + sol.detail +
                    "), yet the PBH pre-flight found (A, B2) stabilisable and (A, C2) detectable (in the pole disk, if one is "
                    "asked), so the LMI is feasible for a large enough gamma: a numerical failure (the plant's scales far "
                    "apart), no proof that no controller exists");
  if (!sdp::has_point(sol.status))
    throw Error(error_code_for(sol.status),
                what + ": " + std::string(sdp::status_message(sol.status)) + (sol.detail.empty() ? "" : ": " + sol.detail));
  return sol;
}



// What one synthesis shares between its solves.
struct SynthesisContext {
  const hinf::GeneralisedPlant& P;  // the user's plant
  const ScaledControllerLmi& S;     // the equilibrated plant and design
  const ControllerDesign& design;   // the user's design (the certificate's)
  const Settings& settings;
  const IterationObserver& observer;
};

// The channel in the equilibrated units: H̃ = D⁻¹ H / ω, Ẽ = E D (‖T_qp‖∞ unchanged).
hinf::UncertaintyChannel scaled_channel(const hinf::UncertaintyChannel& c, const ControllerScaling& s) {
  return {s.state.cwiseInverse().asDiagonal() * c.H / s.time, c.E * s.state.asDiagonal()};
}

// What one attempt at recovering a controller gave.
enum class Recovered {
  Certified,     // certified
  RobustFailed,  // stable, but the robust channel's small-gain test fails: a property of it
  Failed         // no controller, or one the certificate rejects: a numerical failure
};

// The γ of LMI C's point x (its solver's value) in the user's units (docs/maths.md (154)).
double gamma_in_user_units(const ControllerLmi& C, const Eigen::VectorXd& x, const ControllerScaling& s) {
  return C.lmi.value(C.g, x)(0, 0) * s.gamma_factor();
}

// What a recovered controller's certificate makes of the attempt.
Recovered outcome_of(const ControllerCertificate& c) {
  if (c.passed) return Recovered::Certified;
  if (c.stable && !c.robustly_stable) return Recovered::RobustFailed;
  return Recovered::Failed;
}

// The controller of LMI C (minimising γ, solution sol) at back-off b, recovered and
// certified into r: at the γ-optimal point (b = 0) or at the back-off point of (149a)
// at (1 + b) γ*; `why` says why it failed.
Recovered recover_at(const SynthesisContext& x, const ControllerLmi& C, const sdp::Solution& sol,
                     const hinf::UncertaintyChannel* channel, double b, ControllerSynthesisResult& r, std::string& why) {
  const ControllerScaling& sc = x.S.scaling;
  const hinf::GeneralisedPlant& Ps = x.S.plant;
  const double gamma_star = C.lmi.value(C.g, sol.x)(0, 0);  // scaled units
  ControllerPoint pt;
  Eigen::MatrixXd lmi_at_point;
  r.gamma_optimal.reset();
  r.backoff = 0;
  if (b == 0) {
    pt = controller_point(C, Ps, sol.x);
    lmi_at_point = C.lmi.evaluate(sol.x);
  } else {
    const ControllerLmi B = build_controller_backoff_lmi(Ps, x.S.design, gamma_star * (1 + b), channel);
    sdp::Options options = x.settings.solver;  // the margin need only be near its maximum
    options.relative_gap_tol = std::max(x.settings.solver.relative_gap_tol, kBackoffRelativeGap);
    // in the ball γ*'s point was found in (it may be wider than the configured one), not
    // wider: the largest margin grows with the variables, so its point lies on any ball, and
    // a wider one leaves I − R S singular to working precision (docs/maths.md §4.3)
    options.feasibility_radius = std::max(options.feasibility_radius, sol.feasibility_radius);
    const sdp::Solution sb = sdp::minimize_linear(B.lmi, B.lmi.cost_of(*B.t), options, Eigen::VectorXd(),
                                                  staged(x.observer, SolveStage::Backoff));
    r.newton_iterations += sb.newton_total;
    r.time_s += sb.elapsed_s;
    if (!sdp::has_point(sb.status)) {
      why = "gamma back-off (docs/maths.md (149a)): maximising the LMI margin at gamma = " +
            fmt(*B.g_fixed * sc.gamma_factor()) + " failed: " + std::string(sdp::status_message(sb.status)) +
            (sb.detail.empty() ? "" : ": " + sb.detail);
      return Recovered::Failed;
    }
    pt = controller_point(B, Ps, sb.x);
    lmi_at_point = B.lmi.evaluate(sb.x);
    r.gamma_optimal = gamma_in_user_units(C, sol.x, sc);
    r.backoff = b;
  }
  double cond_N = 0;
  try {
    r.controller = unscaled_controller(recover_controller(pt, Ps, &cond_N), sc);
  } catch (const Error& e) {
    why = e.what();
    return Recovered::Failed;
  }
  r.gamma = pt.gamma * sc.gamma_factor();
  r.certificate = certify::certify_controller(x.P, r.controller, r.gamma, x.design.checks());
  r.certificate.cond_N = cond_N;
  r.certificate.lmi_max_eigenvalue =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(lmi_at_point, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
  r.certificate.passed = r.certificate.passed && r.certificate.lmi_max_eigenvalue < 0;
  const Recovered got = outcome_of(r.certificate);
  if (got == Recovered::Failed) why = "the certificate failed";
  return got;
}

// The controller of LMI C recovered and certified into r: at the γ-optimal point, or — asked
// for (settings.gamma_backoff), or when the recovery there fails numerically (I − R S
// singular: the optimum is often reached only in the limit) — at the automatic back-offs in
// turn; when one succeeds after another failed, also at their geometric mean, kept if its
// certified norm is lower (back off only as far as recovery needs, docs/maths.md §6). False
// (and `why`) if no attempt gave a controller. Only numerical failures are retried further
// out: a robust channel that fails is a property of the design.
bool recover_certified(const SynthesisContext& x, const ControllerLmi& C, const sdp::Solution& sol,
                       const hinf::UncertaintyChannel* channel, ControllerSynthesisResult& r, std::string& why) {
  std::vector<double> backoffs{0.0};  // the optimum, then the automatic back-offs
  backoffs.insert(backoffs.end(), std::begin(kAutomaticBackoffs), std::end(kAutomaticBackoffs));
  const bool automatic = !(x.settings.gamma_backoff > 0);
  if (!automatic) backoffs = {x.settings.gamma_backoff};
  double last_failed = 0;
  for (const double b : backoffs) {
    const Recovered got = recover_at(x, C, sol, channel, b, r, why);
    if (got == Recovered::Failed) {
      last_failed = b;
      continue;
    }
    if (got == Recovered::Certified && automatic && last_failed > 0) {
      ControllerSynthesisResult mid = r;
      std::string mid_why;
      const bool better = recover_at(x, C, sol, channel, std::sqrt(last_failed * b), mid, mid_why) == Recovered::Certified &&
                          mid.certificate.closed_loop_hinf_norm < r.certificate.closed_loop_hinf_norm;
      r.newton_iterations = mid.newton_iterations;
      r.time_s = mid.time_s;
      if (better) r = std::move(mid);
    }
    return true;
  }
  return r.controller.A_K.size() > 0;
}

// When no controller is recovered from the ball γ*'s point was found in (I − R S singular to
// working precision at the optimum and at every back-off: singular problems, whose optimum
// is approached only as R and S grow without bound, so that the optimum and the point of
// largest margin both lie on the ball), or one only at a back-off above kNarrowerBallBackoff:
// the LMI is solved again in balls kNarrowerBallFactor narrower at a time, down to
// kNarrowestControllerBall, until one holds no strictly feasible point or recovers a
// controller within kNarrowerBallBackoff of its own optimum; the controller of smallest
// certified norm is kept (docs/maths.md §4.3) — from a narrower ball, a γ* a little higher,
// reported with the wider ball's γ* beside it. True if r is certified.
bool recover_in_narrower_balls(const SynthesisContext& x, const ControllerLmi& C, const sdp::Solution& sol,
                               ControllerSynthesisResult& r, std::string& why) {
  const double gamma_wide = gamma_in_user_units(C, sol.x, x.S.scaling);
  const std::optional<double> wide_norm =
      outcome_of(r.certificate) == Recovered::Certified ? std::optional<double>(r.certificate.closed_loop_hinf_norm)
                                                        : std::nullopt;
  bool certified = wide_norm.has_value();
  int newton = r.newton_iterations;
  double time_s = r.time_s;
  for (double radius = sol.feasibility_radius / kNarrowerBallFactor; radius >= kNarrowestControllerBall;
       radius /= kNarrowerBallFactor) {
    Settings narrow = x.settings;
    narrow.solver.feasibility_radius = radius;
    const SynthesisContext in_ball{x.P, x.S, x.design, narrow, x.observer};
    const sdp::Solution sn = sdp::minimize_linear(C.lmi, C.lmi.cost_of(C.g), narrow.solver, Eigen::VectorXd(),
                                                  staged(x.observer, SolveStage::Controller));
    newton += sn.newton_total;
    time_s += sn.elapsed_s;
    if (sn.status == sdp::Status::Infeasible) break;  // a narrower ball holds no feasible point either
    if (!sdp::has_point(sn.status)) continue;
    ControllerSynthesisResult here = r;
    here.newton_iterations = 0;
    here.time_s = 0;
    here.stopped_short = sn.status == sdp::Status::StoppedShort ? std::optional<std::string>(sn.detail) : std::nullopt;
    std::string why_here;
    const bool got = recover_certified(in_ball, C, sn, nullptr, here, why_here) &&
                     outcome_of(here.certificate) == Recovered::Certified;
    newton += here.newton_iterations;
    time_s += here.time_s;
    if (!got) continue;
    const bool at_its_optimum = here.backoff <= kNarrowerBallBackoff;
    if (!certified || here.certificate.closed_loop_hinf_norm < r.certificate.closed_loop_hinf_norm) {
      here.narrower_ball = radius;
      here.gamma_optimal_wider_ball = gamma_wide;
      here.wider_ball_certified_norm = wide_norm;
      if (!here.gamma_optimal) here.gamma_optimal = gamma_in_user_units(C, sn.x, x.S.scaling);
      r = std::move(here);
      certified = true;
    }
    if (at_its_optimum) break;  // narrower balls only raise γ*
  }
  r.newton_iterations = newton;
  r.time_s = time_s;
  if (!certified) why += " (nor in narrower balls, docs/maths.md §4.3)";
  return certified;
}

// When the nominal controller fails the small-gain test (docs/maths.md (160a)): the least
// ‖T_qp‖∞ any controller achieves (Error Infeasible if a verified dual bound puts it ≥ 1),
// then the controller of (149) with ‖T_qp‖∞ < 1 imposed in the same variables.
void robust_design(const SynthesisContext& x, ControllerSynthesisResult& r) {
  const hinf::UncertaintyChannel channel = scaled_channel(*x.design.robust, x.S.scaling);
  ControllerDesign free = x.S.design;
  free.pole_disk_radius.reset();
  const ControllerLmi Q = build_controller_lmi(robust_channel_plant(x.S.plant, channel), free);
  const sdp::Solution sq = minimize_gamma(Q, x.settings, x.observer, "the robust channel's LMI (docs/maths.md (160a))",
                                          kLeastChannelNormRelativeGap);
  r.newton_iterations += sq.newton_total;
  r.time_s += sq.elapsed_s;
  r.least_robust_channel_norm = Q.lmi.value(Q.g, sq.x)(0, 0);
  if (*r.least_robust_channel_norm >= 1) {  // to full accuracy, for a verified dual bound
    sdp::Solution full;
    try {
      full = minimize_gamma(Q, x.settings, x.observer, "the robust channel's LMI (docs/maths.md (160a))");
    } catch (const Error&) {
      full = sq;  // the end game of a singular problem: the bound below says whether it holds
    }
    const sdp::DualBound bound = sdp::verified_bracket(Q.lmi, Q.lmi.cost_of(Q.g), full.x, x.settings.solver.lmi_margin, {},
                                                      full.centred_path);
    const std::string common = "robust channel (docs/maths.md (160a)): no controller makes ‖T_qp‖∞ < 1";
    if (bound.verified && bound.lower_bound >= 1)
      throw Error(ErrorCode::Infeasible, "infeasible: " + common + ": every controller has ‖T_qp‖∞ >= " +
                                             fmt(bound.lower_bound) + " (verified dual bound; the LMI's optimum is " +
                                             fmt(*r.least_robust_channel_norm) +
                                             "), so small gain cannot prove robust stability for this uncertainty; "
                                             "reduce it (robust:) or model it more finely", "robust");
    throw Error(ErrorCode::CheckFailed,
                "robust channel (docs/maths.md (160a)): no controller with ‖T_qp‖∞ < 1 was found: the least ‖T_qp‖∞ the "
                "LMI reaches is " + fmt(*r.least_robust_channel_norm) + " (not verified as a lower bound: " +
                    bound.detail + "); no controller written", "robust");
  }
  // The scalar D-scaling (p d, q / d) changes nothing in ‖T_qp‖∞ but much in the one
  // Lyapunov function (160a) must share: γ over log10 d, a grid of decades then golden
  // sections around the best (seed 004 at ten times its uncertainty: γ = 2622 at d = 1,
  // 0.098 at d = 1e-3).
  const auto solve_at = [&](double log_d, sdp::Solution* out) {
    hinf::UncertaintyChannel scaled = channel;
    scaled.H *= std::pow(10.0, log_d);
    scaled.E /= std::pow(10.0, log_d);
    const ControllerLmi M = build_robust_controller_lmi(x.S.plant, x.S.design, scaled);
    sdp::Solution sm = sdp::minimize_linear(M.lmi, M.lmi.cost_of(M.g), x.settings.solver, Eigen::VectorXd(),
                                            staged(x.observer, SolveStage::Controller));
    r.newton_iterations += sm.newton_total;
    r.time_s += sm.elapsed_s;
    const double g = sdp::has_point(sm.status) ? M.lmi.value(M.g, sm.x)(0, 0) : INFINITY;
    if (out) *out = std::move(sm);
    return g;
  };
  double best = 0, best_gamma = INFINITY;
  for (double log_d = kLogDLow; log_d <= kLogDHigh; log_d += 1) {
    const double g = solve_at(log_d, nullptr);
    if (g < best_gamma) best_gamma = g, best = log_d;
  }
  if (!std::isfinite(best_gamma))  // not a theorem: the method, not the problem, has failed
    throw Error(ErrorCode::CheckFailed, "robust channel (docs/maths.md (160a)): no D-scaling d in [1e" +
                                           fmt(kLogDLow) + ", 1e" + fmt(kLogDHigh) +
                                           "] made the combined LMI solvable (one Lyapunov function for the "
                                           "performance and ‖T_qp‖∞ < 1: conservative), although the least ‖T_qp‖∞ "
                                           "of any controller is about " + fmt(*r.least_robust_channel_norm) +
                                           "; no controller written (this is not a proof that none exists)", "robust");
  double lo = best - 1, hi = best + 1;  // golden sections on γ(log10 d)
  const double phi = (std::sqrt(5.0) - 1) / 2;
  double a1 = hi - phi * (hi - lo), a2 = lo + phi * (hi - lo);
  double g1 = solve_at(a1, nullptr), g2 = solve_at(a2, nullptr);
  for (int i = 0; i < kGoldenSteps; ++i) {
    if (g1 <= g2) hi = a2, a2 = a1, g2 = g1, a1 = hi - phi * (hi - lo), g1 = solve_at(a1, nullptr);
    else lo = a1, a1 = a2, g1 = g2, a2 = lo + phi * (hi - lo), g2 = solve_at(a2, nullptr);
  }
  if (std::min(g1, g2) < best_gamma) best = g1 <= g2 ? a1 : a2;
  sdp::Solution sm;
  solve_at(best, &sm);
  hinf::UncertaintyChannel scaled = channel;
  scaled.H *= std::pow(10.0, best);
  scaled.E /= std::pow(10.0, best);
  const ControllerLmi M = build_robust_controller_lmi(x.S.plant, x.S.design, scaled);
  r.lmi_order = M.lmi.order();
  r.variables = M.lmi.num_params();
  r.robust_scaling = std::pow(10.0, best);
  r.robust_synthesis = true;
  std::string why;
  if (!recover_certified(x, M, sm, &scaled, r, why)) throw Error(ErrorCode::NumericalFailure, why);
}

}  // namespace

ControllerSynthesisResult synthesize_controller(const hinf::GeneralisedPlant& P, const Settings& settings,
                                                const ControllerDesign& design, const IterationObserver& observer) {
  check_dimensions(P);
  settings.validate();
  if (design.pole_disk_radius && !(*design.pole_disk_radius > 0 && std::isfinite(*design.pole_disk_radius)))
    throw Error(ErrorCode::InvalidInput, "controller.pole_disk_radius = " + fmt(*design.pole_disk_radius) +
                                             ": must be positive and finite", "pole_disk_radius");
  // solved on the equilibrated plant (docs/maths.md (154)), mapped back exactly
  const ScaledControllerLmi S = scaled_controller_lmi(P, design);
  const SynthesisContext x{P, S, design, settings, observer};
  require_stabilisable_detectable(P, design, S);
  const ControllerLmi& C = S.lmi;
  require_memory(C.lmi, settings, "the controller LMI");
  // (149)/(150) (and (153)) is feasible for a large enough γ once the pre-flight above passed
  // (the full-order design, Chilali and Gahinet's common Lyapunov matrix for the intersection
  // of the two regions): a phase I that ends "infeasible" is a numerical failure (on
  // A = [[0, 1], [0, 1e4]] it once claimed "no strictly feasible point", exit 3).
  const sdp::Solution sol =
      minimize_gamma(C, settings, observer, "controller LMI (docs/maths.md (149)/(150))", 0, KnownFeasible::Yes);
  ControllerSynthesisResult r;
  if (sol.status == sdp::Status::StoppedShort) r.stopped_short = sol.detail;
  r.newton_iterations = sol.newton_total;
  r.time_s = sol.elapsed_s;
  r.lmi_order = C.lmi.order();
  r.variables = C.lmi.num_params();
  if (design.pole_disk_radius) {  // γ* of the same problem without the disk, for comparison
    ControllerDesign free = S.design;
    free.pole_disk_radius.reset();
    const ControllerLmi F = build_controller_lmi(S.plant, free);
    const sdp::Solution sf = minimize_gamma(F, settings, nullptr, "controller LMI without the pole disk");
    r.gamma_without_disk = gamma_in_user_units(F, sf.x, S.scaling);
    r.newton_iterations += sf.newton_total;
    r.time_s += sf.elapsed_s;
  }
  std::string why;
  bool recovered = recover_certified(x, C, sol, nullptr, r, why);
  // no controller from γ*'s ball, or one only at a large back-off on a ball-bound optimum
  const bool large_backoff = outcome_of(r.certificate) == Recovered::Certified && sol.ball_bound &&
                             r.backoff > kNarrowerBallBackoff;
  const bool tried_narrower = outcome_of(r.certificate) == Recovered::Failed || large_backoff;
  if (tried_narrower) {
    ControllerSynthesisResult narrow = r;  // r keeps the wider ball's failure to report
    if (recover_in_narrower_balls(x, C, sol, narrow, why)) r = std::move(narrow), recovered = true;
  }
  if (!recovered) throw Error(ErrorCode::NumericalFailure, why);
  const bool discrete = P.time == hinf::TimeDomain::Discrete;
  if (design.robust && r.certificate.stable && !r.certificate.robustly_stable) {
    if (discrete)
      throw Error(ErrorCode::CheckFailed,
                  "robust channel (docs/maths.md (160)): the H-infinity-optimal controller (gamma = " + fmt(r.gamma) +
                      ") has ‖T_qp‖∞ = " + fmt(*r.certificate.robust_channel_norm) +
                      " >= 1, and the robust synthesis (160a) is for continuous-time designs; no controller written",
                  "robust");
    r.nominal_robust_channel_norm = r.certificate.robust_channel_norm;
    robust_design(x, r);
  }
  // What is certified is the closed loop's norm (its certified upper value, a theorem about
  // this controller): γ is that, the smallest the certificate proves — below the LMI's level
  // when the recovery or a back-off left room (docs/maths.md (152b)), never below the norm
  // even within the recovery's slack certify::kClosedLoopNormSlack.
  if (r.certificate.passed) r.gamma = r.certificate.closed_loop_hinf_norm;
  if (!r.certificate.passed)
    throw Error(ErrorCode::NumericalFailure,
                "controller certificate failed: closed loop " + std::string(r.certificate.stable ? "stable" : "unstable") +
                    (r.certificate.poles_in_disk ? "" : ", a pole outside the disk (|lambda| = " +
                                                            fmt(r.certificate.max_pole_modulus) + ")") +
                    (r.certificate.robustly_stable ? "" : ", ‖T_qp‖∞ = " + fmt(*r.certificate.robust_channel_norm) + " >= 1") +
                    ", ‖T_zw‖∞ = " + fmt(r.certificate.closed_loop_hinf_norm) + " against γ = " + fmt(r.gamma) +
                    ", LMI's largest eigenvalue " + fmt(r.certificate.lmi_max_eigenvalue) +
                    ", cond(N) = " + fmt(r.certificate.cond_N) +
                    (tried_narrower ? "; no controller was certified in narrower balls either (docs/maths.md §4.3)" : ""));
  return r;
}

}  // namespace hinf::synth
