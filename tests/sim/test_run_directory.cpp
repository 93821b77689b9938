// The run directory's manifest (sim/run_directory.hpp): a run into a directory that held one
// removes the earlier run's files it does not write again — and nothing else: not a name
// outside the directory, not a sub-directory, not an input of the run, not a file the
// earlier run did not list.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "hinf/common/error.hpp"
#include "hinf/sim/run_directory.hpp"
#include "scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using Files = std::vector<std::pair<std::string, std::string>>;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A plot hook that adds one more output, as the families' plots do.
std::function<void(hinf::AtomicFileSet&)> plot(const fs::path& dir, const std::string& name) {
  return [=](hinf::AtomicFileSet& outputs) { outputs.add((dir / name).string(), "png"); };
}

TEST(RunDirectory, ManifestListsWhatTheRunWrote) {
  const hinf::test::ScratchDir scratch("run_dir_manifest");
  const fs::path dir = scratch.path / "run";
  const auto replaced = hinf::sim::write_run_directory(dir.string(), Files{{"summary.json", "{}"}, {"runs.csv", "r"}},
                                                       {}, plot(dir, "fig.png"));
  EXPECT_FALSE(replaced.previous_run);
  EXPECT_TRUE(replaced.removed.empty());
  EXPECT_EQ(slurp(dir / "manifest.txt"),
            std::string(hinf::sim::kManifestHeader) + "\nsummary.json\nruns.csv\nfig.png\n");
  EXPECT_EQ(listing(dir), (std::vector<std::string>{"fig.png", "manifest.txt", "runs.csv", "summary.json"}));
}

TEST(RunDirectory, ASecondRunRemovesTheFirstRunsFilesItDoesNotWrite) {
  const hinf::test::ScratchDir scratch("run_dir_rerun");
  const fs::path dir = scratch.path / "run";
  hinf::sim::write_run_directory(dir.string(), Files{{"summary.json", "old"}, {"runs.csv", "old"}}, {},
                                 plot(dir, "fig.png"));
  put(dir / "notes.txt", "the user's own file");  // not the run's: stays
  const auto replaced = hinf::sim::write_run_directory(dir.string(), Files{{"summary.json", "new"}}, {}, nullptr);
  EXPECT_TRUE(replaced.previous_run);
  EXPECT_EQ(replaced.removed, (std::vector<std::string>{"runs.csv", "fig.png"}));
  EXPECT_EQ(listing(dir), (std::vector<std::string>{"manifest.txt", "notes.txt", "summary.json"}));
  EXPECT_EQ(slurp(dir / "summary.json"), "new");
  EXPECT_EQ(slurp(dir / "manifest.txt"), std::string(hinf::sim::kManifestHeader) + "\nsummary.json\n");
}

TEST(RunDirectory, AHostileManifestRemovesNothingOutsideTheRunsFiles) {
  const hinf::test::ScratchDir scratch("run_dir_hostile");
  const fs::path dir = scratch.path / "run";
  fs::create_directories(dir / "sub");
  put(scratch.path / "outside.txt", "keep");
  put(dir / "sub" / "inner.txt", "keep");
  put(dir / "scenario.yaml", "keep");  // an input of the run
  fs::create_symlink(scratch.path / "outside.txt", dir / "link.txt");
  put(dir / "manifest.txt", "# a comment\n../outside.txt\n" + (scratch.path / "outside.txt").string() +
                                "\nsub\nsub/inner.txt\n.\n..\nmanifest.txt\nscenario.yaml\nlink.txt\n\n");
  const auto replaced = hinf::sim::write_run_directory(dir.string(), Files{{"summary.json", "{}"}},
                                                       {(dir / "scenario.yaml").string()}, nullptr);
  EXPECT_TRUE(replaced.previous_run);
  EXPECT_TRUE(replaced.removed.empty());
  EXPECT_EQ(slurp(scratch.path / "outside.txt"), "keep");
  EXPECT_EQ(slurp(dir / "sub" / "inner.txt"), "keep");
  EXPECT_EQ(slurp(dir / "scenario.yaml"), "keep");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
}

TEST(RunDirectory, WithoutAManifestNothingIsRemoved) {
  const hinf::test::ScratchDir scratch("run_dir_no_manifest");
  const fs::path dir = scratch.path / "run";
  fs::create_directories(dir);
  put(dir / "fig.png", "a file of unknown origin");
  const auto replaced = hinf::sim::write_run_directory(dir.string(), Files{{"summary.json", "{}"}}, {}, nullptr);
  EXPECT_FALSE(replaced.previous_run);
  EXPECT_TRUE(fs::exists(dir / "fig.png"));
}

TEST(RunDirectory, ARefusedRunLeavesTheEarlierRunWhole) {
  const hinf::test::ScratchDir scratch("run_dir_refused");
  const fs::path dir = scratch.path / "run";
  hinf::sim::write_run_directory(dir.string(), Files{{"summary.json", "old"}, {"runs.csv", "old"}}, {}, nullptr);
  const std::string manifest = slurp(dir / "manifest.txt");
  put(dir / "in.yaml", "input");
  EXPECT_THROW(hinf::sim::write_run_directory(dir.string(), Files{{"summary.json", "new"}, {"in.yaml", "x"}},
                                              {(dir / "in.yaml").string()}, nullptr),
               hinf::Error);
  EXPECT_EQ(slurp(dir / "summary.json"), "old");
  EXPECT_EQ(slurp(dir / "runs.csv"), "old");
  EXPECT_EQ(slurp(dir / "manifest.txt"), manifest);
}

}  // namespace
