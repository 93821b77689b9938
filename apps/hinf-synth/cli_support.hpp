// Helpers shared by the subcommands: loading inputs, printing numbers and reports.
#pragma once
#include <cstdio>
#include <string>

#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/synthesis.hpp"

namespace hinf::cli {

// Gains file → Filter, with dimensions checked against the plant (Error InvalidInput).
hinf::Filter filter_from_gains(const runtime_yaml::GainsFile& g, const hinf::Plant& plant,
                                const std::string& path);
// "%.10g"
std::string num(double v);
// Coefficient ranges of the plant matrices (USER-PAIN #5), for --verbose.
void print_coefficient_ranges(const hinf::Plant& plant, std::FILE* out);
// SDP-solver-style iteration table on stderr.
// The --verbose iteration table on stderr (a header whenever a new SDP starts).
class IterationTable {
 public:
  void operator()(const synth::IterationReport& r);

 private:
  bool started_ = false;
  synth::SolveStage stage_ = synth::SolveStage::Synthesis;
};

}  // namespace hinf::cli
