// synthesize_controller, certify_controller (controller_synthesis.hpp).
#include "hinf/synth/controller_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>
#include <string>

#include "controller_lmi.hpp"
#include "controller_scaling.hpp"
#include "hinf/certify/balance.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/common/error.hpp"
#include "hinf/lmi/sdpa_format.hpp"
#include "hinf/sdp/path_following.hpp"
#include "pipeline.hpp"

namespace hinf::synth {

namespace {

// When the γ-optimal point does not give a controller (I − R S numerically singular, or a
// certificate lost to round-off), the back-offs (149a) tried in turn.
constexpr double kAutomaticBackoffs[] = {1e-7, 1e-5, 1e-3};
// The back-off's margin is maximised to this relative gap (as the filters', docs/maths.md §6).
constexpr double kBackoffRelativeGap = 1e-3;
// The closed-loop norm may exceed the solver's γ by this much (the recovery's round-off).
constexpr double kNormSlack = 1e-6;
// Relative accuracy of the closed-loop norm.
constexpr double kNormTolerance = 1e-10;

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

// ‖T_qp‖∞ of the closed loop (147) `cl` of P: p enters the plant's state by H, q = E x
// (docs/maths.md (160)); the controller's states are neither perturbed nor read.
double robust_channel_norm(const hinf::GeneralisedPlant& P, const hinf::StateSpace& cl,
                           const hinf::UncertaintyChannel& channel) {
  const Eigen::Index n = P.n(), ncl = cl.A.rows();
  if (channel.H.rows() != n || channel.E.cols() != n)
    throw Error(ErrorCode::InvalidInput, "controller.robust: H must have " + std::to_string(n) + " rows and E " +
                                             std::to_string(n) + " columns (the plant's states), got H " +
                                             std::to_string(channel.H.rows()) + "x" + std::to_string(channel.H.cols()) +
                                             " and E " + std::to_string(channel.E.rows()) + "x" +
                                             std::to_string(channel.E.cols()), "robust");
  hinf::StateSpace t;
  t.A = cl.A;
  t.B = Eigen::MatrixXd::Zero(ncl, channel.H.cols());
  t.B.topRows(n) = channel.H;
  t.C = Eigen::MatrixXd::Zero(channel.E.rows(), ncl);
  t.C.leftCols(n) = channel.E;
  t.D = Eigen::MatrixXd::Zero(channel.E.rows(), channel.H.cols());
  return (P.time == hinf::TimeDomain::Discrete ? certify::discrete_hinf_norm(t, kNormTolerance)
                                                : certify::continuous_hinf_norm(t, kNormTolerance))
      .norm;
}

// A mode of A counts as unreached (unseen) when the PBH matrix [A − λI, X] ([A − λI; X]) has a
// singular value this small relative to its scale (docs/maths.md (126)).
constexpr double kPbhRelativeTolerance = 1e-10;

// The first eigenvalue λ of A outside the stability region (Re λ ≥ 0, or |λ| ≥ 1 in discrete
// time) at which [A − λI; X] loses rank, if any: an unstable mode X does not see.
std::optional<std::complex<double>> unseen_unstable_mode(const Eigen::MatrixXd& A, const Eigen::MatrixXd& X,
                                                         bool discrete) {
  const Eigen::Index n = A.rows();
  Eigen::ComplexEigenSolver<Eigen::MatrixXd> es(A, false);
  Eigen::MatrixXd AX(n + X.rows(), n);
  AX << A, X;
  const double scale = std::max(1.0, AX.norm());
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
    const std::complex<double> lambda = es.eigenvalues()(i);
    if (discrete ? std::abs(lambda) < 1 : lambda.real() < 0) continue;
    Eigen::MatrixXcd pbh(n + X.rows(), n);
    pbh << A.cast<std::complex<double>>() - lambda * Eigen::MatrixXcd::Identity(n, n), X.cast<std::complex<double>>();
    if (Eigen::JacobiSVD<Eigen::MatrixXcd>(pbh).singularValues()(n - 1) <= kPbhRelativeTolerance * scale) return lambda;
  }
  return std::nullopt;
}

// No controller stabilises the loop unless (A, B2) is stabilisable and (A, C2) detectable
// (checked on the equilibrated plant): Error(Infeasible) naming the mode.
void require_stabilisable_detectable(const hinf::GeneralisedPlant& P) {
  const bool discrete = P.time == hinf::TimeDomain::Discrete;
  const char* region = discrete ? "|λ| ≥ 1" : "Re λ ≥ 0";
  const auto text = [](std::complex<double> z) {
    return fmt(z.real()) + (z.imag() == 0 ? "" : (z.imag() > 0 ? " + " : " - ") + fmt(std::abs(z.imag())) + "i");
  };
  if (const auto l = unseen_unstable_mode(P.A.transpose(), P.B2.transpose(), discrete))
    throw Error(ErrorCode::Infeasible, "infeasible: (A, B2) is not stabilisable: the mode λ = " + text(*l) + " of A (" +
                                           region + ") is not reached by the control u, so no controller makes the "
                                           "closed loop stable (PBH test, docs/maths.md (126))");
  if (const auto l = unseen_unstable_mode(P.A, P.C2, discrete))
    throw Error(ErrorCode::Infeasible, "infeasible: (A, C2) is not detectable: the mode λ = " + text(*l) + " of A (" +
                                           region + ") is not seen in the measurement y, so no controller makes the "
                                           "closed loop stable (PBH test, docs/maths.md (126))");
}

}  // namespace

namespace {

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
sdp::Solution minimize_gamma(const ControllerLmi& C, const Settings& settings, const IterationObserver& observer,
                             const std::string& what) {
  const sdp::Solution sol = sdp::minimize_linear(C.lmi, C.lmi.cost_of(C.g), solver_options(settings), Eigen::VectorXd(),
                                                 staged(observer, SolveStage::Controller));
  if (sol.status != sdp::Status::Solved)
    throw Error(error_code_for(sol.status),
                what + ": " + std::string(sdp::status_message(sol.status)) + (sol.detail.empty() ? "" : ": " + sol.detail));
  return sol;
}

}  // namespace

ControllerCertificate certify_controller(const hinf::GeneralisedPlant& P, const hinf::Controller& K, double gamma,
                                         const ControllerDesign& design) {
  ControllerCertificate c;
  const hinf::StateSpace cl = hinf::closed_loop(P, K);
  const Eigen::VectorXcd poles = certify::balanced_eigenvalues(cl.A);
  c.closed_loop_poles.assign(poles.data(), poles.data() + poles.size());
  const bool discrete = P.time == hinf::TimeDomain::Discrete;
  c.stability_margin_value = discrete ? poles.cwiseAbs().maxCoeff() : poles.real().maxCoeff();
  c.stable = discrete ? c.stability_margin_value < 1 : c.stability_margin_value < 0;
  c.max_pole_modulus = poles.cwiseAbs().maxCoeff();
  c.poles_in_disk = !design.pole_disk_radius || c.max_pole_modulus < *design.pole_disk_radius;
  if (!c.stable) {
    c.closed_loop_hinf_norm = INFINITY;
    return c;
  }
  const certify::HinfNorm h =
      discrete ? certify::discrete_hinf_norm(cl, kNormTolerance) : certify::continuous_hinf_norm(cl, kNormTolerance);
  c.closed_loop_hinf_norm = h.norm;
  c.peak_frequency = h.peak_frequency;
  if (design.robust) {
    c.robust_channel_norm = robust_channel_norm(P, cl, *design.robust);
    c.robustly_stable = *c.robust_channel_norm < 1;
  }
  c.passed = c.poles_in_disk && c.robustly_stable && c.closed_loop_hinf_norm <= gamma * (1 + kNormSlack);
  return c;
}

ControllerSynthesisResult synthesize_controller(const hinf::GeneralisedPlant& P, const Settings& settings,
                                                const ControllerDesign& design, const IterationObserver& observer) {
  check_dimensions(P);
  settings.validate();
  if (design.pole_disk_radius && !(*design.pole_disk_radius > 0 && std::isfinite(*design.pole_disk_radius)))
    throw Error(ErrorCode::InvalidInput, "controller.pole_disk_radius = " + fmt(*design.pole_disk_radius) +
                                             ": must be positive and finite", "pole_disk_radius");
  // solved on the equilibrated plant (docs/maths.md (154)), mapped back exactly
  const ScaledControllerLmi S = scaled_controller_lmi(P, design);
  const ControllerScaling& sc = S.scaling;
  const hinf::GeneralisedPlant& Ps = S.plant;
  require_stabilisable_detectable(Ps);
  const ControllerLmi& C = S.lmi;
  require_memory(C.lmi, settings, "the controller LMI");
  const sdp::Solution sol = minimize_gamma(C, settings, observer, "controller LMI (docs/maths.md (149)/(150))");
  ControllerSynthesisResult r;
  r.newton_iterations = sol.newton_total;
  r.time_s = sol.elapsed_s;
  r.lmi_order = C.lmi.order();
  r.variables = C.lmi.num_params();
  const double gamma_star = C.lmi.value(C.g, sol.x)(0, 0);  // scaled units
  if (design.pole_disk_radius) {  // γ* of the same problem without the disk, for comparison
    ControllerDesign free = S.design;
    free.pole_disk_radius.reset();
    const ControllerLmi F = build_controller_lmi(Ps, free);
    const sdp::Solution sf = minimize_gamma(F, settings, nullptr, "controller LMI without the pole disk");
    r.gamma_without_disk = F.lmi.value(F.g, sf.x)(0, 0) * sc.gamma_factor();
    r.newton_iterations += sf.newton_total;
    r.time_s += sf.elapsed_s;
  }
  // The controller at the γ-optimal point, or — asked for (settings.gamma_backoff), or when
  // the recovery there fails numerically (I − R S singular: the optimum is often reached
  // only in the limit) — at the back-off point of (149a).
  std::vector<double> backoffs;
  if (settings.gamma_backoff > 0) backoffs = {settings.gamma_backoff};
  else backoffs = {0.0, kAutomaticBackoffs[0], kAutomaticBackoffs[1], kAutomaticBackoffs[2]};
  std::string why;
  for (const double b : backoffs) {
    ControllerPoint pt = controller_point(C, Ps, sol.x);
    Eigen::MatrixXd lmi_at_point = C.lmi.evaluate(sol.x);
    if (b > 0) {
      const ControllerLmi B = build_controller_backoff_lmi(Ps, S.design, gamma_star * (1 + b));
      sdp::Options options = solver_options(settings);  // the margin need only be near its maximum
      options.relative_gap_tol = std::max(settings.relative_gap_tol, kBackoffRelativeGap);
      const sdp::Solution sb = sdp::minimize_linear(B.lmi, B.lmi.cost_of(*B.t), options, Eigen::VectorXd(),
                                                    staged(observer, SolveStage::Backoff));
      r.newton_iterations += sb.newton_total;
      r.time_s += sb.elapsed_s;
      if (sb.status != sdp::Status::Solved) {
        why = "gamma back-off (docs/maths.md (149a)): maximising the LMI margin at gamma = " +
              fmt(*B.g_fixed * sc.gamma_factor()) + " failed: " + std::string(sdp::status_message(sb.status)) +
              (sb.detail.empty() ? "" : ": " + sb.detail);
        continue;
      }
      pt = controller_point(B, Ps, sb.x);
      lmi_at_point = B.lmi.evaluate(sb.x);
      r.gamma_optimal = gamma_star * sc.gamma_factor();
      r.backoff = b;
    }
    double cond_N = 0;
    try {
      r.controller = unscaled_controller(recover_controller(pt, Ps, &cond_N), sc);
    } catch (const Error& e) {
      why = e.what();
      continue;
    }
    r.gamma = pt.gamma * sc.gamma_factor();
    r.certificate = certify_controller(P, r.controller, r.gamma, design);
    r.certificate.cond_N = cond_N;
    r.certificate.lmi_max_eigenvalue =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(lmi_at_point, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
    r.certificate.passed = r.certificate.passed && r.certificate.lmi_max_eigenvalue < 0;
    // only numerical failures are retried further out; a robust channel that fails is a property
    if (r.certificate.passed || (r.certificate.stable && !r.certificate.robustly_stable)) break;
    why = "the certificate failed";
  }
  if (r.controller.A_K.size() == 0 && P.n() > 0) throw Error(ErrorCode::NumericalFailure, why);
  // What is certified is the closed loop's norm (its certified upper value): γ is never
  // written below it, even within the recovery's slack kNormSlack.
  if (r.certificate.passed) r.gamma = std::max(r.gamma, r.certificate.closed_loop_hinf_norm);
  const double cond_N = r.certificate.cond_N;
  const ControllerCertificate& c = r.certificate;
  if (!c.robustly_stable && c.stable && c.poles_in_disk && c.lmi_max_eigenvalue < 0 &&
      c.closed_loop_hinf_norm <= r.gamma * (1 + kNormSlack))
    throw Error(ErrorCode::CheckFailed,
                "robust channel (docs/maths.md (160)): the H-infinity-optimal controller (gamma = " + fmt(r.gamma) +
                    ") has ‖T_qp‖∞ = " + fmt(*c.robust_channel_norm) +
                    " >= 1: small gain does not prove robust stability for this uncertainty; no controller written",
                "robust");
  if (!r.certificate.passed)
    throw Error(ErrorCode::NumericalFailure,
                "controller certificate failed: closed loop " + std::string(r.certificate.stable ? "stable" : "unstable") +
                    (r.certificate.poles_in_disk ? "" : ", a pole outside the disk (|lambda| = " +
                                                            fmt(r.certificate.max_pole_modulus) + ")") +
                    ", ‖T_zw‖∞ = " + fmt(r.certificate.closed_loop_hinf_norm) + " against γ = " + fmt(r.gamma) +
                    ", LMI's largest eigenvalue " + fmt(r.certificate.lmi_max_eigenvalue) + ", cond(N) = " + fmt(cond_N));
  return r;
}

}  // namespace hinf::synth
