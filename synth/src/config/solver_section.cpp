// `solver:`: one key per field of hinf::synth::Settings, spelt as the field; `filter:`, its form.
#include "config/sections.hpp"

namespace hinf::synth {

Settings read_solver_section(const YamlReader& reader, const YAML::Node& solver) {
  reader.check_map(solver, "solver",
                   {"lmi_margin", "relative_gap_tol", "barrier_growth", "feasibility_radius",
                    "max_newton_per_centering", "max_iterations", "time_limit_s", "max_memory_mb",
                    "gamma_backoff", "stability_samples", "seed", "verbose"});
  Settings s;
  const auto number = [&](const char* key, double& field) {
    if (const YAML::Node n = solver[key]) field = reader.number(n, std::string("solver.") + key);
  };
  const auto integer = [&](const char* key, int& field) {
    if (const YAML::Node n = solver[key]) field = reader.integer(n, std::string("solver.") + key);
  };
  number("lmi_margin", s.solver.lmi_margin);
  number("relative_gap_tol", s.solver.relative_gap_tol);
  number("barrier_growth", s.solver.barrier_growth);
  number("feasibility_radius", s.solver.feasibility_radius);
  integer("max_newton_per_centering", s.solver.max_newton_per_centering);
  integer("max_iterations", s.solver.max_iterations);
  number("time_limit_s", s.solver.time_limit_s);
  number("max_memory_mb", s.max_memory_mb);
  number("gamma_backoff", s.gamma_backoff);
  integer("stability_samples", s.stability_samples);
  if (const YAML::Node n = solver["seed"]) s.seed = reader.unsigned_integer(n, "solver.seed");
  if (const YAML::Node n = solver["verbose"]) s.verbose = reader.boolean(n, "solver.verbose");
  return s;
}

void read_filter_section(const YamlReader& reader, const YAML::Node& filter, Settings& settings) {
  const YamlMap f = reader.map(filter, "filter", {"form", "estimate"});
  const std::string form = f.choice("form", {"auto", "augmented", "observer"}, "auto");
  settings.form = form == "observer" ? FormChoice::Observer : form == "augmented" ? FormChoice::Augmented : FormChoice::Auto;
  const bool filtered = f.choice("estimate", {"predicted", "filtered"}, "predicted") == "filtered";
  settings.estimate = filtered ? Estimate::Filtered : Estimate::Predicted;
  if (filtered && settings.form == FormChoice::Augmented)
    f.fail("estimate", "'filtered' is the observer form's a-posteriori estimate (docs/maths.md §18.6); "
                       "Theorem 1's augmented filter (filter.form: augmented) has none: use filter.form: observer or auto");
}

}  // namespace hinf::synth
