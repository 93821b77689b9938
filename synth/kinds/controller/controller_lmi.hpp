// The output-feedback H∞ synthesis LMIs of docs/maths.md §26 (Scherer–Gahinet–Chilali's
// linearising change of variables) written once, block by block, as data for the generic
// LMI layer, and the controller's recovery from their solution.
#pragma once
#include <optional>

#include "hinf/lmi/lmi_problem.hpp"
#include "hinf/models/controller.hpp"
#include "hinf/models/generalised_plant.hpp"
#include "hinf/synth/controller_synthesis.hpp"

namespace hinf::synth {

struct ControllerLmi {
  lmi::LmiProblem lmi{std::vector<int>{}};
  lmi::VarId R, S, Ahat, Bhat, Chat, g;  // g = γ (enters linearly); unused when γ is fixed
  std::optional<lmi::VarId> Dhat;        // absent for a strictly proper controller (D_K = 0)
  std::optional<lmi::VarId> t;           // the back-off's margin: every block ≺ t I (γ fixed)
  std::optional<double> g_fixed;         // γ of the back-off LMI
};

// Continuous time (149): blocks n, n, nw, nz of the bounded-real LMI and n, n of
// [S I; I R] ≻ 0. Discrete time (150): blocks n, n, n, n, nw, nz. Minimise g.
// With design.pole_disk_radius = r, four more n-blocks hold the disk LMI (153).
ControllerLmi build_controller_lmi(const hinf::GeneralisedPlant& P, const ControllerDesign& design);

// The γ back-off (docs/maths.md (149a)): the same LMI at the fixed γ = g_fixed with every
// diagonal block ≺ t I; minimise t (the point of largest margin, as for the filters, §6).
ControllerLmi build_controller_backoff_lmi(const hinf::GeneralisedPlant& P, const ControllerDesign& design,
                                           double g_fixed, const hinf::UncertaintyChannel* robust = nullptr);

// Robust synthesis (docs/maths.md (160a), continuous time): (149) with four more blocks, the
// bounded-real LMI of the channel p → q (robust_channel_plant) at γ = 1 in the same
// variables — a controller with ‖T_zw‖∞ < γ and ‖T_qp‖∞ < 1 (one Lyapunov function for both).
ControllerLmi build_robust_controller_lmi(const hinf::GeneralisedPlant& P, const ControllerDesign& design,
                                          const hinf::UncertaintyChannel& robust);

// The plant of the channel p → q: B1 = H, C1 = E, D11 = D12 = D21 = 0 (its γ-optimal
// controller minimises ‖T_qp‖∞, docs/maths.md (160a)).
hinf::GeneralisedPlant robust_channel_plant(const hinf::GeneralisedPlant& P, const hinf::UncertaintyChannel& channel);

// The change of variables' values at a solution x of the LMI.
struct ControllerPoint {
  Eigen::MatrixXd R, S, Ahat, Bhat, Chat, Dhat;
  double gamma = 0;
};
ControllerPoint controller_point(const ControllerLmi& C, const hinf::GeneralisedPlant& P, const Eigen::VectorXd& x);

// Recovery (151): N Mᵀ = I − R S split by its SVD U Σ Vᵀ as N = U Σ^½, M = V Σ^½,
// then D_K, C_K, B_K, A_K. cond(N) (= cond(I − R S)^½) is returned in *cond_N.
// Throws Error(NumericalFailure) if I − R S is numerically singular.
hinf::Controller recover_controller(const ControllerPoint& pt, const hinf::GeneralisedPlant& P, double* cond_N);

}  // namespace hinf::synth
