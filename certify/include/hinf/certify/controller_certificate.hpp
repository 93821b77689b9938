// The independent certificate of an output-feedback controller (docs/maths.md §26): computed
// from the plant and the controller alone — the closed loop (147), its poles, its H∞ norm by
// the symplectic pencil, the pole disk and the small-gain test of a robust channel — and
// never from the LMI or the solver that produced the controller (the layer rule of
// cmake/HinfLayers.cmake holds for controllers as for filters).
#pragma once
#include <complex>
#include <optional>
#include <vector>

#include "hinf/models/controller.hpp"
#include "hinf/models/generalised_plant.hpp"
#include "hinf/models/state_space.hpp"

namespace hinf::certify {

// What a controller is checked for beside ‖T_zw‖∞ ≤ γ.
struct ControllerChecks {
  // Every closed-loop pole inside |λ| < r (Chilali–Gahinet disk, docs/maths.md (153)).
  std::optional<double> pole_disk_radius;
  // Unstructured uncertainty ΔA = H F E, ‖F‖ ≤ 1 (docs/maths.md (160)): the small-gain test
  // ‖T_qp‖∞ < 1 of the closed loop from p (entering by H) to q = E x.
  std::optional<hinf::UncertaintyChannel> robust;
};

struct ControllerCertificate {
  // Closed loop (147) from the recovered controller: Hurwitz (continuous) or Schur
  // (discrete), and its spectral abscissa (max Re λ) or spectral radius.
  bool stable = false;
  double stability_margin_value = 0;
  std::vector<std::complex<double>> closed_loop_poles;
  // ‖T_zw‖∞ of the closed loop, certified upper value (symplectic pencil; continuous time
  // through the bilinear map (152)), and where it peaks (rad/s or rad/sample).
  double closed_loop_hinf_norm = 0;
  double peak_frequency = 0;
  // Filled by the synthesis, not by certify_controller: the synthesis LMI at the solver's
  // point, its largest eigenvalue (< 0 strictly), and cond(N), N Mᵀ = I − R S (the
  // recovery's conditioning, (151)).
  double lmi_max_eigenvalue = 0;
  double cond_N = 0;
  // The largest pole modulus, and whether every pole is inside the disk asked for (true
  // when none was).
  double max_pole_modulus = 0;
  bool poles_in_disk = true;
  // ‖T_qp‖∞ (certified upper value) when a robust channel was given; robust stability by
  // small gain when < 1.
  std::optional<double> robust_channel_norm;
  bool robustly_stable = true;  // true when no channel was given
  // stable, in the disk, robustly stable, ‖T_zw‖∞ ≤ γ(1 + kClosedLoopNormSlack) (and, from
  // a synthesis, the LMI strictly negative at its point)
  bool passed = false;
};

// The closed-loop norm may exceed the level γ by this much (the recovery's round-off).
inline constexpr double kClosedLoopNormSlack = 1e-6;

// Error(InvalidInput) naming the first matrix of K whose dimensions do not fit P
// (A_K n_K×n_K, B_K n_K×ny, C_K nu×n_K, D_K nu×ny), before any arithmetic on them.
void require_controller_fits(const hinf::GeneralisedPlant& P, const hinf::Controller& K);

// The certificate of controller K on plant P at level γ. Error(InvalidInput) as
// require_controller_fits, or when a robust channel does not fit P (H n rows, E n columns).
ControllerCertificate certify_controller(const hinf::GeneralisedPlant& P, const hinf::Controller& K, double gamma,
                                         const ControllerChecks& checks);

// ‖T_qp‖∞ (certified upper value) of the closed loop `cl` (147) of P: p enters the plant's
// state by H, q = E x (docs/maths.md (160)); the controller's states are neither perturbed
// nor read. Error(InvalidInput) when H or E does not fit P.
double robust_channel_norm(const hinf::GeneralisedPlant& P, const hinf::StateSpace& cl,
                           const hinf::UncertaintyChannel& channel);

}  // namespace hinf::certify
