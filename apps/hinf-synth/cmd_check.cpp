// hinf-synth check CONFIG --golden GOLDEN.yaml [--rtol R]: regression of the synthesis.
// The filters are compared as transfer functions (docs/maths.md (61), [D14]): another state-space
// realisation of the same filter passes; a real change fails. Because the optimal
// filter is not unique, a golden filter whose transfer function differs is still
// accepted when it remains certified for the config at the golden γ (within
// min(rtol, 1e-6)): an equally optimal filter.
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "controller_files.hpp"
#include "hinf/synth/regression.hpp"

namespace hinf::cli {

void add_check(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("check", "re-synthesise and compare with a golden gains or controller file (exit 0 same, 1 changed)");
  auto config = std::make_shared<std::string>();
  auto golden = std::make_shared<std::string>();
  auto rtol = std::make_shared<double>(1e-6);
  cmd->add_option("config", *config, "config YAML")->required();
  cmd->add_option("--golden", *golden, "golden gains YAML")->required();
  cmd->add_option("--rtol", *rtol, "relative tolerance on gamma and on the filters' transfer-function difference")
      ->check(CLI::Range(1e-14, 1.0));
  cmd->callback([=, &action] {
    action = [=]() -> int {
      if (is_controller_config(*config)) return check_controller_file(*config, *golden, *rtol);
      const ConfigAndFilter in = load_config_and_filter(*config, *golden);
      const synth::SynthConfig& cfg = in.config;
      const runtime_yaml::GainsFile& g = in.gains;
      const hinf::Filter& gf = in.filter;
      if (!g.gamma)
        throw hinf::Error(hinf::ErrorCode::InvalidInput, *golden + ": golden file has no 'gamma'");
      const synth::SynthesisResult r = synth::synthesize(cfg.plant, cfg.settings);
      const synth::GoldenComparison cmp = synth::compare_with_golden(cfg, gf, *g.gamma, r, *rtol);
      std::string why;
      if (cmp.golden_recertified) {
        const synth::Certificate& c = *cmp.golden_recertified;
        why = "        the golden filter on this config: nominal Hinf norm " + num(c.hinf_norm_nominal) +
              ", robust analysis LMI " +
              (c.robust_feasible_at_gamma ? "feasible" : "infeasible (best scaled norm " + num(c.robust_scaled_norm) + ")") +
              " at the golden gamma" +
              (cmp.same_filter ? ": an equally optimal filter (the optimum is not unique)\n" : "\n");
      }
      std::cout << "gamma:  golden " << num(*g.gamma) << ", now " << num(r.gamma) << ", relative change "
                << num(cmp.gamma_relative_change) << (cmp.same_gamma ? "  ok" : "  CHANGED") << "\n"
                << "filter: ||F_golden - F_now||_inf / ||F_golden||_inf = " << num(cmp.filter_difference.relative)
                << " (transfer functions y -> z_F)" << (cmp.same_filter ? "  ok" : "  CHANGED") << "\n"
                << why;
      if (!g.config_sha256.empty() && g.config_sha256 != cfg.sha256)
        std::cout << "note: the golden file was generated from a config with another sha256 ("
                  << g.config_sha256.substr(0, 12) << "... vs " << cfg.sha256.substr(0, 12) << "...)\n";
      std::cout << (cmp.same() ? "same (rtol " + num(*rtol) + ")\n" : "CHANGED (rtol " + num(*rtol) + ")\n");
      return cmp.same() ? 0 : 1;
    };
  });
}

}  // namespace hinf::cli
