// The policies of `hinf-synth verify` and `check` for controllers (docs/maths.md §26): a
// claimed controller against its config, and a new synthesis against a golden controller
// file. Everything is recomputed from the controller and the config's plant
// (certify::certify_controller); the application only prints.
#pragma once
#include <optional>
#include <string>

#include "hinf/models/controller.hpp"
#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/controller_synthesis.hpp"

namespace hinf::synth {

struct ControllerVerification {
  ControllerCertificate certificate;  // at the claimed γ (the LMI's eigenvalue is not part of it)
  bool holds = false;                 // stable, in the disk, robust if asked, ‖T_zw‖∞ ≤ γ (1 + 1e-6)
};

// Error(InvalidInput) if the controller's dimensions do not fit the plant. `P` and `checks`:
// the config's (config.plant, config.design.checks()), or its sampled plant's for a
// discretised controller (docs/maths.md (161b)).
ControllerVerification verify_controller(const hinf::GeneralisedPlant& P, const certify::ControllerChecks& checks,
                                         const hinf::Controller& K, double claimed_gamma);

struct ControllerGoldenComparison {
  double gamma_relative_change = 0;  // |γ_now − γ_golden| / γ_golden
  bool same_gamma = false;
  // ‖K_golden − K_now‖∞ / ‖K_golden‖∞ (transfer functions y → u), when both controllers
  // are stable; empty otherwise (an unstable controller has no H∞ norm).
  std::optional<double> controller_difference;
  // Within rtol — or the golden controller still certified for the config at the golden
  // γ·(1 + min(rtol, 1e-6)): an equally optimal controller (the optimum is not unique).
  bool same_controller = false;
  std::optional<ControllerCertificate> golden_recertified;
  bool same() const { return same_gamma && same_controller; }
};

ControllerGoldenComparison compare_controller_with_golden(const ControllerConfig& config, const hinf::Controller& golden,
                                                          double golden_gamma, const ControllerSynthesisResult& now,
                                                          double rtol);

}  // namespace hinf::synth
