// `hill:`, the physical Hill/CW model of docs/maths.md §9 (units: rad/s, s, kg).
#include <cmath>

#include "config/sections.hpp"
#include "hinf/common/number_text.hpp"

namespace hinf::synth {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

}  // namespace

HillPlantSpec read_hill_section(const YamlReader& reader, const YAML::Node& hill) {
  reader.check_map(hill, "hill",
                   {"orbital_rate", "orbital_period", "chaser_mass", "K", "sample_time",
                    "delta_bar", "discretisation", "B", "D", "C", "L"});
  const auto required = [&](const std::string& key, const char* what) {
    const YAML::Node node = hill[key];
    if (!node) reader.fail(hill, "missing key 'hill." + key + "' (" + what + ")");
    return node;
  };

  HillPlantSpec model;
  const YAML::Node rate = hill["orbital_rate"];
  const YAML::Node period = hill["orbital_period"];
  if (rate && period)
    reader.fail(period, "give exactly one of 'hill.orbital_rate' (rad/s) and "
                        "'hill.orbital_period' (s), not both");
  if (!rate && !period)
    reader.fail(hill, "missing key 'hill.orbital_rate' (rad/s; or 'hill.orbital_period' in s)");
  if (rate) {
    model.orbital_rate = reader.number(rate, "hill.orbital_rate");
  } else {
    const double T_orbit = reader.number(period, "hill.orbital_period");
    if (!std::isfinite(T_orbit) || !(T_orbit > 0))
      reader.fail(period, "hill.orbital_period = " + number_text(T_orbit) +
                              ": must be finite and > 0 (s)");
    model.orbital_rate = kTwoPi / T_orbit;  // ω₀ = 2π / T_orbit
  }
  model.chaser_mass = reader.number(required("chaser_mass", "kg"), "hill.chaser_mass");
  model.sample_time = reader.number(required("sample_time", "s"), "hill.sample_time");
  model.delta_bar = reader.number(required("delta_bar", "|delta| <= delta_bar"), "hill.delta_bar");

  if (const YAML::Node d = hill["discretisation"])
    model.discretisation = reader.choice(d, "hill.discretisation", {"euler", "zoh"}) == "euler"
                               ? hinf::models::Discretisation::Euler
                               : hinf::models::Discretisation::ZeroOrderHold;

  if (const YAML::Node K = hill["K"]) model.K = reader.matrix(K, "hill.K");
  model.B = reader.matrix(required("B", "6 x p process-noise input"), "hill.B");
  model.D = reader.matrix(required("D", "m x q measurement-noise input"), "hill.D");
  if (const YAML::Node C = hill["C"]) model.C = reader.matrix(C, "hill.C");
  if (const YAML::Node L = hill["L"]) model.L = reader.matrix(L, "hill.L");
  return model;
}

}  // namespace hinf::synth
