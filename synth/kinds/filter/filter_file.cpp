// Gains files read against a filter config (hinf/synth/filter_file.hpp).
#include "hinf/synth/filter_file.hpp"

#include <utility>

#include "hinf/common/error.hpp"

namespace hinf::synth {

Filter filter_from_gains(const runtime_yaml::GainsFile& g, const Plant& plant, const std::string& path) {
  const auto need = [&](const char* key, const Eigen::MatrixXd& M, Eigen::Index r, Eigen::Index c) {
    if (M.rows() != r || M.cols() != c)
      throw Error(ErrorCode::InvalidInput, path + ": filter." + key + " is " + std::to_string(M.rows()) + "x" +
                                               std::to_string(M.cols()) + ", the config's plant needs " +
                                               std::to_string(r) + "x" + std::to_string(c));
  };
  need("A_F", g.A_F, plant.n(), plant.n());
  need("B_F", g.B_F, plant.n(), plant.m());
  need("C_F", g.C_F, plant.l(), plant.n());
  need("G_F", g.G_F, plant.n(), plant.r());
  Filter f;
  f.A_F = g.A_F;
  f.B_F = g.B_F;
  f.C_F = g.C_F;
  f.G_F = g.G_F;
  if (g.observer_form) {
    need("K", g.K, plant.n(), plant.m());
    f.form = FilterForm::Observer;
    f.K = g.K;
  }
  if (g.filtered) {  // docs/maths.md (140)
    need("M", g.M, plant.n(), plant.m());
    need("D_F", g.D_F, plant.l(), plant.m());
    f.M = g.M;
    f.D_F = g.D_F;
  }
  return f;
}

ConfigAndFilter load_config_and_filter(const std::string& config_path, const std::string& gains_path) {
  SynthConfig config = load_config(config_path);
  runtime_yaml::GainsFile gains = runtime_yaml::load_gains_file(gains_path);
  Filter filter = filter_from_gains(gains, config.plant, gains_path);
  return {std::move(config), std::move(gains), std::move(filter)};
}

}  // namespace hinf::synth
