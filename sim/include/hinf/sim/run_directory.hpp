// A campaign's run directory, written all or nothing (hinf/common/atomic_file.hpp): every
// output goes to a temporary first and all are renamed together, and no output replaces a
// file the run read (the scenario, and every gains, controller or synthesis config file it
// names: hinf-sim's outputs such as gains.yaml or controller.yaml must not land on them).
// The directory's manifest.txt lists the files the run wrote, so that a later run into the same
// directory removes those it does not write again (plots of a run drawn with plots, then
// --no-plots; a filter renamed): a run directory never mixes two runs' files.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hinf/common/atomic_file.hpp"

namespace hinf::sim {

// Creates `dir` and its parents: Error(InvalidInput) naming it if it cannot.
void create_output_directory(const std::string& dir);

// The manifest's name in a run directory, and its first line.
inline constexpr const char* kManifestName = "manifest.txt";
inline constexpr const char* kManifestHeader =
    "# hinf-sim run directory: the files of this run, one per line (a later run into this directory "
    "removes those it does not write again)";

// What writing a run directory found of an earlier run there (its manifest.txt).
struct RunDirectoryReplaced {
  bool previous_run = false;         // the directory held a run (a manifest) before
  std::vector<std::string> removed;  // that run's files this one did not write, removed
};

// Writes `files` (name in `dir`, content), what `plots` (may be empty) adds to the same set and
// the manifest, then commits; then removes the files an earlier run's manifest lists that this
// run did not write (plain names in `dir` only, regular files only, never an input).
// `inputs`: every file the run read. Error(InvalidInput) naming the file when an output would
// replace an input or cannot be written (nothing is then written); PlotError from `plots`.
RunDirectoryReplaced write_run_directory(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& files,
                         const std::vector<std::string>& inputs,
                         const std::function<void(hinf::AtomicFileSet& outputs)>& plots);

}  // namespace hinf::sim
