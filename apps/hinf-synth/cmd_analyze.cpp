// hinf-synth analyze CONFIG GAINS.yaml [--json]
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "controller_files.hpp"
#include "hinf/synth/analysis.hpp"

namespace hinf::cli {

namespace {

using Json = nlohmann::ordered_json;  // keys in the order written

// A number as the text output prints it (num: 10 significant digits); null if not finite.
Json json_num(double v) { return std::isfinite(v) ? Json(std::strtod(num(v).c_str(), nullptr)) : Json(nullptr); }

// θ rad/sample at sample time T is θ/(2πT) Hz.
double peak_hz(const synth::FilterAnalysis& a, double T) { return a.hinf_norm_peak_frequency / (2 * kPi * T); }

// One line of JSON: the gains path and the analysis (keys in this order).
std::string analysis_json(const std::string& gains_path, const runtime_yaml::GainsFile& g,
                          const synth::FilterAnalysis& a, std::optional<double> sample_time) {
  Json j = Json::object();
  j["gains"] = gains_path;
  j["claimed_gamma"] = g.gamma ? json_num(*g.gamma) : Json(nullptr);
  j["spectral_radius_nominal"] = json_num(a.spectral_radius_nominal);
  j["hinf_norm_nominal"] = json_num(a.hinf_norm_nominal);
  j["hinf_norm_peak_frequency"] = json_num(a.hinf_norm_peak_frequency);
  j["sample_time_s"] = sample_time ? json_num(*sample_time) : Json(nullptr);
  j["hinf_norm_peak_frequency_hz"] = sample_time ? json_num(peak_hz(a, *sample_time)) : Json(nullptr);
  j["spectral_radius_sampled_max"] = json_num(a.spectral_radius_sampled_max);
  j["robust_bound"] = json_num(a.robust_bound);
  if (a.has_worst_F) {
    j["worst_F_gain"] = json_num(a.worst_F_gain);
    Json rows = Json::array();
    for (Eigen::Index r = 0; r < a.worst_F.rows(); ++r) {
      Json row = Json::array();
      for (Eigen::Index c = 0; c < a.worst_F.cols(); ++c) row.push_back(json_num(a.worst_F(r, c)));
      rows.push_back(std::move(row));
    }
    j["worst_F"] = std::move(rows);
    j["worst_F_evaluations"] = a.worst_F_evaluations;
  }
  if (!a.delta_grid.empty()) {
    j["worst_delta"] = json_num(a.worst_delta);
    j["worst_delta_hinf_norm"] = json_num(a.worst_delta_hinf_norm);
    Json grid = Json::array();
    for (const auto& p : a.delta_grid) {
      Json point = Json::object();
      point["delta"] = json_num(p.delta);
      point["spectral_radius"] = json_num(p.spectral_radius);
      point["hinf_norm"] = json_num(p.hinf_norm);
      grid.push_back(std::move(point));
    }
    j["delta_grid"] = std::move(grid);
  }
  // A path that is not UTF-8 is written with U+FFFD rather than refused.
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace

void add_analyze(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("analyze", "nominal Hinf norm, robust bound, the worst case found over the uncertainty (and the delta grid of hill configs) of any filter");
  const auto args = add_config_gains_args(*cmd, "gains YAML");
  auto json = std::make_shared<bool>(false);
  auto points = std::make_shared<int>(41);
  cmd->add_flag("--json", *json, "print JSON instead of text");
  cmd->add_option("--delta-points", *points, "grid points over [-delta_bar, delta_bar] (hill configs)")
      ->check(CLI::Range(2, 100001));
  cmd->callback([=, &action] {
    action = [=]() -> int {
      if (is_controller_config(args->config)) return analyze_controller_file(args->config, args->gains, *json);
      const ConfigAndFilter in = load_config_and_filter(args->config, args->gains);
      const synth::SynthConfig& cfg = in.config;
      const runtime_yaml::GainsFile& g = in.gains;
      const synth::FilterAnalysis a = synth::analyze_filter(cfg.plant, cfg.hill, in.filter, cfg.settings, *points);
      if (*json) {
        std::cout << analysis_json(args->gains, g, a, cfg.sample_time()) << "\n";
        return 0;
      }
      std::cout << "gains                      " << args->gains << (g.gamma ? " (claims gamma " + num(*g.gamma) + ")" : "") << "\n"
                << "spectral radius (nominal)  " << num(a.spectral_radius_nominal) << "\n"
                << "nominal Hinf norm          " << num(a.hinf_norm_nominal) << " at " << num(a.hinf_norm_peak_frequency) << " rad/sample"
                << (cfg.sample_time() ? " = " + num(peak_hz(a, *cfg.sample_time())) + " Hz (T = " + num(*cfg.sample_time()) + " s)" : "")
                << "\n"
                << "sampled spectral radius    " << num(a.spectral_radius_sampled_max) << " (max over admissible F)\n"
                << "robust bound (LMI)         " << num(a.robust_bound)
                << (cfg.plant.uncertain() ? "" : " (no uncertainty: the nominal norm, LMI (50)'s infimum)") << "\n";
      if (a.has_worst_F)
        std::cout << "worst case found           " << num(a.worst_F_gain) << " at a constant admissible F ("
                  << a.worst_F_evaluations << " norms; sampled, then a local search): the worst-case gain lies in ["
                  << num(a.worst_F_gain) << ", " << num(a.robust_bound) << "]\n";
      if (!a.delta_grid.empty())
        std::cout << "worst case on delta grid   " << num(a.worst_delta_hinf_norm) << " at delta = " << num(a.worst_delta)
                  << " (" << a.delta_grid.size() << " points, exact plant)\n";
      return 0;
    };
  });
}

}  // namespace hinf::cli
