// A gains file read against a filter config: the filter it describes, every field the file
// can carry (G_F, the observer form's K, the filtered estimate's M and D_F) checked against
// the config's plant (docs/file-formats.md "Gains files").
#pragma once
#include <string>

#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/synth/config.hpp"

namespace hinf::synth {

// Gains file → Filter, with dimensions checked against the plant (Error InvalidInput naming
// the file, the key and both dimensions).
Filter filter_from_gains(const runtime_yaml::GainsFile& g, const Plant& plant, const std::string& path);

// A config and a gains file read together (in that order), with the gains' filter.
struct ConfigAndFilter {
  SynthConfig config;
  runtime_yaml::GainsFile gains;
  Filter filter;  // checked against the config's plant
};
ConfigAndFilter load_config_and_filter(const std::string& config_path, const std::string& gains_path);

}  // namespace hinf::synth
