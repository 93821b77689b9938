// hinf-synth analyze CONFIG GAINS.yaml [--json]
#include <cmath>
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/synth/analysis.hpp"

namespace hinf::cli {

namespace {
std::string json_num(double v) { return std::isfinite(v) ? num(v) : "null"; }
}  // namespace

void add_analyze(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("analyze", "nominal Hinf norm, robust bound and delta-grid worst case of any filter");
  auto config = std::make_shared<std::string>();
  auto gains = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto points = std::make_shared<int>(41);
  cmd->add_option("config", *config, "config YAML")->required();
  cmd->add_option("gains", *gains, "gains YAML")->required();
  cmd->add_flag("--json", *json, "print JSON instead of text");
  cmd->add_option("--delta-points", *points, "grid points over [-delta_bar, delta_bar] (hill configs)")
      ->check(CLI::Range(2, 100001));
  cmd->callback([=, &action] {
    action = [=]() -> int {
      const synth::SynthConfig cfg = synth::load_config(*config);
      const runtime_yaml::GainsFile g = runtime_yaml::load_gains_file(*gains);
      const hinf::Filter f = filter_from_gains(g, cfg.plant, *gains);
      const synth::FilterAnalysis a = synth::analyze_filter(cfg.plant, cfg.hill, f, cfg.settings, *points);
      if (*json) {
        std::cout << "{\"gains\": \"" << *gains << "\", \"claimed_gamma\": " << (g.gamma ? json_num(*g.gamma) : "null")
                  << ", \"spectral_radius_nominal\": " << json_num(a.spectral_radius_nominal)
                  << ", \"hinf_norm_nominal\": " << json_num(a.hinf_norm_nominal)
                  << ", \"hinf_norm_peak_frequency\": " << json_num(a.hinf_norm_peak_frequency)
                  << ", \"spectral_radius_sampled_max\": " << json_num(a.spectral_radius_sampled_max)
                  << ", \"robust_bound\": " << json_num(a.robust_bound);
        if (!a.delta_grid.empty()) {
          std::cout << ", \"worst_delta\": " << json_num(a.worst_delta)
                    << ", \"worst_delta_hinf_norm\": " << json_num(a.worst_delta_hinf_norm) << ", \"delta_grid\": [";
          for (size_t i = 0; i < a.delta_grid.size(); ++i)
            std::cout << (i ? ", " : "") << "{\"delta\": " << json_num(a.delta_grid[i].delta)
                      << ", \"spectral_radius\": " << json_num(a.delta_grid[i].spectral_radius)
                      << ", \"hinf_norm\": " << json_num(a.delta_grid[i].hinf_norm) << "}";
          std::cout << "]";
        }
        std::cout << "}\n";
        return 0;
      }
      std::cout << "gains                      " << *gains << (g.gamma ? " (claims gamma " + num(*g.gamma) + ")" : "") << "\n"
                << "spectral radius (nominal)  " << num(a.spectral_radius_nominal) << "\n"
                << "nominal Hinf norm          " << num(a.hinf_norm_nominal) << " at " << num(a.hinf_norm_peak_frequency) << " rad/sample\n"
                << "sampled spectral radius    " << num(a.spectral_radius_sampled_max) << " (max over admissible F)\n"
                << "robust bound (LMI)         " << num(a.robust_bound) << "\n";
      if (!a.delta_grid.empty())
        std::cout << "worst case on delta grid   " << num(a.worst_delta_hinf_norm) << " at delta = " << num(a.worst_delta)
                  << " (" << a.delta_grid.size() << " points, exact plant)\n";
      return 0;
    };
  });
}

}  // namespace hinf::cli
