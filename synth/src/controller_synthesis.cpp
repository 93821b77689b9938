// synthesize_controller, certify_controller (controller_synthesis.hpp).
#include "hinf/synth/controller_synthesis.hpp"

#include <algorithm>
#include <cmath>
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

}  // namespace

namespace {

// The equilibrated plant, the disk in its time unit, and the LMI on them.
struct ScaledControllerLmi {
  ControllerScaling scaling;
  hinf::GeneralisedPlant plant;
  ControllerLmi lmi;
};
ScaledControllerLmi scaled_controller_lmi(const hinf::GeneralisedPlant& P, const ControllerDesign& design) {
  ScaledControllerLmi s;
  s.scaling = choose_controller_scaling(P);
  s.plant = scaled_generalised_plant(P, s.scaling);
  ControllerDesign scaled_design = design;
  if (design.pole_disk_radius && P.time == hinf::TimeDomain::Continuous)
    scaled_design.pole_disk_radius = *design.pole_disk_radius / s.scaling.time;
  s.lmi = build_controller_lmi(s.plant, scaled_design);
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
  c.passed = c.poles_in_disk && c.closed_loop_hinf_norm <= gamma * (1 + kNormSlack);
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
  const ControllerLmi& C = S.lmi;
  require_memory(C.lmi, settings, "the controller LMI");
  const sdp::Solution sol = sdp::minimize_linear(C.lmi, C.lmi.cost_of(C.g), solver_options(settings), Eigen::VectorXd(),
                                                 staged(observer, SolveStage::Controller));
  if (sol.status != sdp::Status::Solved)
    throw Error(error_code_for(sol.status), "controller LMI (docs/maths.md (149)/(150)): " +
                                                std::string(sdp::status_message(sol.status)) +
                                                (sol.detail.empty() ? "" : ": " + sol.detail));
  const ControllerPoint pt = controller_point(C, Ps, sol.x);
  ControllerSynthesisResult r;
  double cond_N = 0;
  r.controller = unscaled_controller(recover_controller(pt, Ps, &cond_N), sc);
  r.gamma = pt.gamma * sc.gamma_factor();
  r.certificate = certify_controller(P, r.controller, r.gamma, design);
  r.certificate.cond_N = cond_N;
  r.certificate.lmi_max_eigenvalue =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(C.lmi.evaluate(sol.x), Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
  r.certificate.passed = r.certificate.passed && r.certificate.lmi_max_eigenvalue < 0;
  // What is certified is the closed loop's norm (its certified upper value): γ is never
  // written below it, even within the recovery's slack kNormSlack.
  if (r.certificate.passed) r.gamma = std::max(r.gamma, r.certificate.closed_loop_hinf_norm);
  r.newton_iterations = sol.newton_total;
  r.lmi_order = C.lmi.order();
  r.variables = C.lmi.num_params();
  r.time_s = sol.elapsed_s;
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
