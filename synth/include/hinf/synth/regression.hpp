// The policies of `hinf-synth check` (a synthesis against a golden result) and `verify`
// (claimed gains against a config), in the library so that tests call them without a
// subprocess; the application only prints them.
#pragma once
#include <optional>
#include <string>

#include "hinf/certify/filter_compare.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

struct GoldenComparison {
  double gamma_relative_change = 0;           // |γ_now − γ_golden| / γ_golden
  certify::FilterDifference filter_difference;  // transfer functions, docs/maths.md (61)
  bool same_gamma = false;
  // Transfer functions within rtol — or, since the optimal filter is not unique, the golden
  // filter still certified for the config at the golden γ·(1 + min(rtol, 1e-6)): an equally
  // optimal filter (then golden_recertified holds that certificate).
  bool same_filter = false;
  std::optional<Certificate> golden_recertified;
  bool same() const { return same_gamma && same_filter; }
};

GoldenComparison compare_with_golden(const SynthConfig& config, const Filter& golden_filter, double golden_gamma,
                                     const SynthesisResult& now, double rtol);

struct Verification {
  Certificate certificate;          // checks 2–4 at the claimed γ
  bool holds = false;               // the claimed γ is certified
  // When it does not hold and the error system is stable: the bound the filter does achieve,
  // max(robust analysis LMI minimised, nominal H∞ norm), or why it could not be computed.
  std::optional<double> achieved_bound;
  std::string achieved_unknown_reason;
};

Verification verify_gains(const SynthConfig& config, const Filter& filter, double claimed_gamma);

}  // namespace hinf::synth
