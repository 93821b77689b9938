// hinf-synth verify CONFIG GAINS.yaml: re-derive the certificate of given gains.
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "controller_files.hpp"
#include "hinf/synth/regression.hpp"

namespace hinf::cli {
namespace {

// "(A_F, B_F, C_F, G_F = A - K C, K, L, G to 1e-16)" or "(NOT A - K C, K, L, G: relative
// difference ...)" above 1e-12; for a filtered estimate with C_F, D_F = L - L M C, L M (docs/maths.md (140)).
std::string observer_realisation_text(const hinf::Filter& f, double mismatch) {
  const std::string names = f.filtered() ? "A_F, B_F, C_F, D_F, G_F" : "A_F, B_F, C_F, G_F";
  const std::string values = f.filtered() ? "A - K C, K, L - L M C, L M, G" : "A - K C, K, L, G";
  return mismatch <= 1e-12 ? " (" + names + " = " + values + " to " + num(mismatch) + ")"
                           : " (NOT " + values + ": relative difference " + num(mismatch) + ")";
}

// "multiplier λ", or with F block-diagonal "multipliers [λ₁, λ₂] (one per block of F)".
std::string multipliers_text(const synth::Certificate& c) {
  if (c.robust_block_multipliers.size() == 0) return "multiplier " + num(c.robust_multiplier);
  std::string out = "multipliers [";
  for (Eigen::Index b = 0; b < c.robust_block_multipliers.size(); ++b)
    out += (b ? ", " : "") + num(c.robust_block_multipliers(b));
  return out + "] (one per block of F)";
}

}  // namespace

void add_verify(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("verify", "re-derive the certificate (docs/maths.md §7, checks 2-4) of a gains file against a config, or of a controller file against a controller config");
  const auto args = add_config_gains_args(*cmd, "gains YAML (must state gamma)");
  cmd->callback([=, &action] {
    action = [=]() -> int {
      if (is_controller_config(args->config)) return verify_controller_file(args->config, args->gains);
      const ConfigAndFilter in = load_config_and_filter(args->config, args->gains);
      const synth::SynthConfig& cfg = in.config;
      const runtime_yaml::GainsFile& g = in.gains;
      const hinf::Filter& f = in.filter;
      if (!g.gamma)
        throw hinf::Error(hinf::ErrorCode::InvalidInput, args->gains + ": no 'gamma' to verify (use 'analyze' for a bound)");
      const synth::Verification v = synth::verify_gains(cfg, f, *g.gamma);
      const synth::Certificate& c = v.certificate;
      std::cout << "claimed gamma         " << num(*g.gamma) << "\n"
                << "filter form           " << to_string(f.form) << (f.filtered() ? ", filtered estimate" : "")
                << (f.form == hinf::FilterForm::Observer ? observer_realisation_text(f, c.observer_mismatch)
                                                         : std::string())
                << "\n"
                << "schur stable          " << (c.schur_stable ? "yes" : "NO") << " (spectral radius nominal "
                << num(c.spectral_radius_nominal) << ", sampled max " << num(c.spectral_radius_sampled_max)
                << " over " << c.stability_samples << " F)\n";
      if (c.schur_stable) {
        std::cout << "nominal Hinf norm     " << num(c.hinf_norm_nominal) << (c.hinf_norm_ok ? " <= gamma" : " > gamma  FAIL") << "\n"
                  << "robust analysis LMI   "
                  << (c.robust_feasible_at_gamma
                          ? "feasible at gamma (S-procedure " + multipliers_text(c) + ", scaled norm " +
                                num(c.robust_scaled_norm) + " < 1; feasible down to " +
                                num(c.robust_bound) + ")"
                          : "infeasible at gamma (best scaled norm " + num(c.robust_scaled_norm) + " >= 1)  FAIL")
                  << "\n";
      }
      const std::string achieved = !c.schur_stable   ? std::string("none (unstable)")
                                   : v.achieved_bound ? num(*v.achieved_bound)
                                                      : "unknown (" + v.achieved_unknown_reason + ")";
      std::cout << (v.holds ? std::string("verified: the gains file's gamma holds\n")
                            : "NOT verified: the bound actually achieved is " + achieved + "\n");
      return v.holds ? 0 : 1;
    };
  });
}

}  // namespace hinf::cli
