// A campaign's run directory, written all or nothing (hinf/common/atomic_file.hpp): every
// output goes to a temporary first and all are renamed together, and no output replaces a
// file the run read (the scenario, and every gains, controller or synthesis config file it
// names: hinf-sim's outputs such as gains.yaml or controller.yaml must not land on them).
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hinf/common/atomic_file.hpp"

namespace hinf::sim {

// Creates `dir` and its parents: Error(InvalidInput) naming it if it cannot.
void create_output_directory(const std::string& dir);

// Writes `files` (name in `dir`, content) and what `plots` (may be empty) adds to the same
// set, then commits. `inputs`: every file the run read. Error(InvalidInput) naming the file
// when an output would replace an input or cannot be written (nothing is then written);
// PlotError from `plots`.
void write_run_directory(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& files,
                         const std::vector<std::string>& inputs,
                         const std::function<void(hinf::AtomicFileSet& outputs)>& plots);

}  // namespace hinf::sim
