// Parsing: YAML → LinearPlantExperiment (linear_plant_scenario_yaml.hpp), with the project's one
// strict YAML reader; the gains each filter names are obtained here (gains_source.hpp).
#include "hinf/sim/linear_plant_scenario_yaml.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "hinf/sim/gains_source.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/synthesis.hpp"
#include "scenario_fields.hpp"
#include "scenario_paths.hpp"

namespace hinf::sim {

namespace {

void read_noise(const YamlMap& top, LinearPlantScenario& s) {
  if (!top.has("noise")) return;
  const YamlMap m = top.map("noise", {"process_std", "measurement_std", "initial_state_std"});
  s.process_std = standard_deviation(m, "process_std", s.process_std, 1.0, ZeroSigma::Allowed);
  s.measurement_std = standard_deviation(m, "measurement_std", s.measurement_std, 1.0, ZeroSigma::Allowed);
  s.initial_state_std = standard_deviation(m, "initial_state_std", s.initial_state_std, 1.0, ZeroSigma::Allowed);
}

// Column names runs.csv already has: a parameter may not take one (linear_plant_report.cpp).
const std::vector<std::string> kRunsColumns{"run", "seed", "filter", "error_rms", "predicted_error_rms", "error_max",
                                            "diverged"};

// truth.parameters: {NAME: value | random} over the config's named parameters that enter A;
// the others at their nominal.
void read_truth_parameters(const YamlMap& truth, const hinf::synth::SynthConfig& config, LinearPlantScenario& s) {
  std::vector<std::string> names;
  for (const auto& b : config.parameter_blocks) names.push_back(b.parameter.name);
  if (names.empty())
    truth.fail("parameters", "the config names no parameter that enters system.A (`parameters:`, docs/file-formats.md)");
  const YamlMap m = truth.map("parameters", names);
  for (const auto& b : config.parameter_blocks) {
    const hinf::synth::UncertainParameter& p = b.parameter;
    TruthParameter t{p.name, p.nominal, p.radius(), p.low, p.high, b.columns, p.nominal};
    if (std::find(kRunsColumns.begin(), kRunsColumns.end(), p.name) != kRunsColumns.end())
      m.fail(p.name, "a parameter named as a column of runs.csv; rename it in the config");
    if (m.has(p.name)) {
      const YAML::Node v = m.get(p.name);
      if (v.IsScalar() && v.Scalar() == "random") {
        t.value.reset();
      } else {
        t.value = m.finite(p.name);
        if (*t.value < p.low || *t.value > p.high)
          m.fail_value(p.name, *t.value, "must lie in the parameter's range [" + number_text(p.low) + ", " +
                                             number_text(p.high) + "], or be `random` (drawn per run on it)");
      }
    }
    s.truth_parameters.push_back(t);
  }
}

void read_truth(const YamlMap& top, const hinf::synth::SynthConfig& config, LinearPlantScenario& s) {
  if (!top.has("truth")) return;
  const YamlMap m = top.map("truth", {"uncertainty_delta", "parameters"});
  if (m.has("parameters")) {
    if (m.has("uncertainty_delta"))
      m.fail("parameters", "give the truth by uncertainty_delta or by parameters, not both");
    read_truth_parameters(m, config, s);
    return;
  }
  if (!m.has("uncertainty_delta")) return;
  if (!s.plant.uncertain())
    m.fail("uncertainty_delta", "the config's plant has no uncertainty (`uncertainty:` or `parameters:`)");
  const YAML::Node v = m.get("uncertainty_delta");
  if (v.IsScalar() && v.Scalar() == "random") {
    s.random_uncertainty = true;
    return;
  }
  s.uncertainty_delta = m.finite("uncertainty_delta");
  if (std::abs(s.uncertainty_delta) > 1)
    m.fail_value("uncertainty_delta", s.uncertainty_delta,
                 "must be in [-1, 1] (‖F‖ ≤ 1), or `random` (each block's δ drawn per run)");
}

// The gains a filter's settings name, checked against the plant's m and l.
struct GainsReader {
  const hinf::synth::SynthConfig& config;
  std::optional<ObtainedGains> synthesised, kalman;  // each computed once

  ObtainedGains obtain(const YamlMap& f, const std::string& type, const std::string& scenario_path,
                       std::vector<std::string>& inputs) {
    if (f.has("gains")) {
      if (type != "hinf") f.fail("gains", "only with type: hinf (a gains file of an H-infinity filter)");
      const std::string path = resolve_scenario_file(f, "gains", scenario_path);
      inputs.push_back(path);
      ObtainedGains g = obtain_gains({path, ""}, nullptr, KnownInput::Zero);
      const Plant& P = config.plant;
      if (g.gains.B_F.cols() != P.m() || g.gains.C_F.rows() != P.l())
        f.fail("gains", "'" + path + "' is a filter for m = " + std::to_string(g.gains.B_F.cols()) + ", l = " +
                            std::to_string(g.gains.C_F.rows()) + "; the config's plant has m = " + std::to_string(P.m()) +
                            ", l = " + std::to_string(P.l()));
      return g;
    }
    if (type == "hinf") {
      if (!synthesised)
        synthesised = obtained_from(hinf::synth::synthesize(config.plant, config.settings), config,
                                    "synthesised from " + config.path);
      return *synthesised;
    }
    if (!kalman)
      kalman = obtained_from(hinf::synth::kalman_predictor(config.plant, config.settings, config.kalman_noise), config,
                             "Kalman predictor of " + config.path);
    return *kalman;
  }
};

LinearPlantFilter read_filter(const YamlMap& filters, const std::string& name, GainsReader& gains,
                              LinearPlantExperiment& e) {
  require_column_name(filters, name, "a filter's name");
  const YamlMap f = filters.map(name, {"type", "gains"}, EmptyMap::Allowed);
  LinearPlantFilter out;
  out.name = name;
  out.type = name == "hinf" || name == "kalman" ? name : "";
  if (f.has("type")) out.type = f.choice("type", {"hinf", "kalman"});
  if (out.type.empty()) f.reader().fail(f.node(), "filters." + name + ": needs type: hinf or kalman");
  ObtainedGains g = gains.obtain(f, out.type, e.path, e.inputs);
  out.gains = std::move(g.gains);
  out.gamma = g.gamma;
  out.origin = std::move(g.origin);
  out.gains_yaml = std::move(g.gains_yaml);
  return out;
}

void read_metrics(const YamlMap& top, const LinearPlantScenario& s, LinearPlantRunOptions& o) {
  o.window_start = s.duration / 2;
  if (!top.has("metrics")) return;
  const YamlMap m = top.map("metrics", {"steady_state_start"});
  o.window_start = m.nonnegative("steady_state_start", o.window_start);
  if (o.window_start > s.duration)
    m.fail_value("steady_state_start", o.window_start, "must be within the run, duration " + number_text(s.duration));
}

}  // namespace

LinearPlantExperiment parse_linear_plant_scenario(const std::string& text, const std::string& source_name) {
  const YamlReader reader(source_name);
  const YAML::Node root = reader.load(text, "empty scenario; expected a map with scenario: linear_plant");
  const YamlMap top =
      reader.map(root, "", {"scenario", "config", "duration", "noise", "truth", "filters", "metrics", "plots"});
  LinearPlantExperiment e;
  e.path = source_name;
  LinearPlantScenario& s = e.scenario;
  top.required("config", "the synthesis config whose plant is simulated");
  s.config_path = resolve_scenario_file(top, "config", source_name);
  e.inputs.push_back(s.config_path);
  const hinf::synth::SynthConfig config = hinf::synth::load_config(s.config_path);
  s.plant = config.plant;
  s.sample_time = config.sample_time().value_or(1.0);
  top.required("duration", "s, or samples when the config states no sample time");
  s.duration = top.positive("duration");
  require_whole_samples(top, s.duration, s.sample_time);
  read_noise(top, s);
  read_truth(top, config, s);
  read_metrics(top, s, e.options);
  GainsReader gains{config, std::nullopt, std::nullopt};
  read_named_filters(top, static_cast<std::size_t>(kMaxLinearPlantFilters), "hinf, kalman",
                     [&](const YamlMap& filters, const std::string& name) {
                       e.filters.push_back(read_filter(filters, name, gains, e));
                     });
  e.plots = top.boolean("plots", e.plots);
  return e;
}

}  // namespace hinf::sim
