// Output-feedback H∞ controller synthesis (docs/maths.md §26): the LMI of Scherer–Gahinet–
// Chilali in the change of variables (R, S, Â, B̂, Ĉ, D̂), solved by the same barrier
// method as the filters, the controller recovered by (151), and an independent
// certificate computed from the controller alone.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "hinf/certify/controller_certificate.hpp"
#include "hinf/models/controller.hpp"
#include "hinf/models/generalised_plant.hpp"
#include "hinf/synth/settings.hpp"
#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

// What is asked of the controller beside γ (config controller.strictly_proper,
// controller.pole_disk_radius).
struct ControllerDesign {
  bool strictly_proper = true;  // D_K = 0: no measurement noise fed straight to u
  // Closed-loop poles confined to |λ| < r (Chilali–Gahinet disk, docs/maths.md (153)): the
  // cure for the γ-optimal controller's ill-conditioning (very fast poles, large cond(N)).
  std::optional<double> pole_disk_radius;
  // Unstructured uncertainty ΔA = H F E, ‖F‖ ≤ 1 (docs/maths.md (160)): the certificate adds
  // the small-gain test ‖T_qp‖∞ < 1 of the closed loop from p (entering by H) to q = E x.
  std::optional<hinf::UncertaintyChannel> robust;
  // What the certificate checks beside γ: the disk and the robust channel.
  certify::ControllerChecks checks() const { return {pole_disk_radius, robust}; }
};

// The controller's certificate is certify's (hinf/certify/controller_certificate.hpp):
// computed from the plant and the controller alone, never from the solver.
using certify::ControllerCertificate;

struct ControllerSynthesisResult {
  hinf::Controller controller;
  double gamma = 0;  // certified: ‖T_zw‖∞ ≤ γ, the closed loop's certified norm (docs/maths.md (152b))
  // With settings.gamma_backoff > 0: the LMI's optimum γ* before the back-off (the solver's
  // value; the controller written is the back-off's, at (1 + b) γ*).
  std::optional<double> gamma_optimal;
  double backoff = 0;  // b of that back-off: settings.gamma_backoff, or the automatic one
                       // (1e-7, 1e-5, 1e-3, 1e-2, 5e-2 in turn) when I − R S is singular at the optimum
  // With a pole disk: the LMI's optimum without it (the solver's value, for comparison; no
  // controller is recovered there).
  std::optional<double> gamma_without_disk;
  // When no controller could be recovered in the ball of γ*'s point, or one only at a large
  // back-off, and a narrower ball's is certified with a smaller norm (docs/maths.md §4.3):
  // that ball's radius, the wider ball's optimum γ* (the solver's value; gamma_optimal is then
  // the narrower ball's), and the wider ball's controller's certified norm if it had one.
  std::optional<double> narrower_ball, gamma_optimal_wider_ball, wider_ball_certified_norm;
  // With a robust channel that the H∞-optimal controller fails (‖T_qp‖∞ ≥ 1, its value here):
  // the least ‖T_qp‖∞ any controller achieves (the LMI's optimum), and the controller written
  // is then the robust design of docs/maths.md (160a).
  std::optional<double> nominal_robust_channel_norm, least_robust_channel_norm;
  bool robust_synthesis = false;
  double robust_scaling = 1;  // the D-scaling d of the robust design (p d, q / d)
  ControllerCertificate certificate;
  // Set when the solver stopped short of its gap tolerance on the controller LMI (its end
  // game failed on round-off): why, and the last centred point's relative gap. The
  // controller is then recovered from that point and certified as any other.
  std::optional<std::string> stopped_short;
  int newton_iterations = 0;
  int lmi_order = 0, variables = 0;
  double time_s = 0;
};

// Minimises γ over the LMI (149) (continuous) or (150) (discrete), with the disk (153) if
// asked; D_K = 0 when strictly proper. With settings.gamma_backoff = b > 0 the controller is
// recovered at γ_b = (1 + b) γ*, at the point of the LMI's largest margin (149a): a far
// better-conditioned recovery (cond(N) 7.5e4 → 39 on seed 004's plant at b = 0.05) for a
// slightly larger γ. Error(InvalidInput) on inconsistent dimensions or non-finite entries,
// Error(Infeasible) if the LMI has no solution, Error(NumericalFailure) if the solver or
// the certificate fails (nothing is returned that the certificate has not passed).
// `observer` (may be empty) hears the solver's progress, as synthesize's does.
ControllerSynthesisResult synthesize_controller(const hinf::GeneralisedPlant& plant, const Settings& settings,
                                                const ControllerDesign& design,
                                                const IterationObserver& observer = nullptr);

// The LMI synthesize_controller minimises (on the equilibrated plant, (154)), in SDPA sparse
// format; the comment says which variable is γ̃ and the factor s_z/s_w with γ = γ̃ s_z/s_w.
std::string controller_sdpa(const hinf::GeneralisedPlant& plant, const ControllerDesign& design,
                            const std::string& comment);

}  // namespace hinf::synth
