// What the end-to-end tests of hinf-sim's scenario families share: a fresh output directory,
// running hinf-sim on configs/scenarios/NAME.yaml, reading its CSV files, and the metrics of
// summary.json (a number for one run, {mean, max, …} for several).
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace sim_cli_test {

namespace fs = std::filesystem;

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// A fresh directory under the temporary directory, named for the family, the case and the process.
inline fs::path fresh_dir(const std::string& family, const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("hinf_sim_" + family + "_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

// Runs hinf-sim on the scenario file SCENARIO with ARGS into OUT, its output into LOG; its
// exit code (−1 if it did not exit).
inline int run_scenario_file(const fs::path& scenario, const std::string& args, const fs::path& out,
                             const fs::path& log) {
  const std::string cmd = std::string(HINF_SIM_EXE) + " " + scenario.string() + " -o " + out.string() + " " + args +
                          " > " + log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs hinf-sim on configs/scenarios/NAME.yaml with ARGS into OUT; its exit code (its output
// printed when it fails).
inline int run_scenario(const std::string& name, const std::string& args, const fs::path& out) {
  const fs::path scenario = fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / (name + ".yaml");
  const fs::path log = out.string() + ".log";
  const int rc = run_scenario_file(scenario, args + " --quiet", out, log);
  if (rc != 0) std::cerr << slurp(log);
  fs::remove(log);
  return rc;
}

struct Columns {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  // The column's index, −1 if there is none.
  int col(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : static_cast<int>(it - header.begin());
  }
};

inline Columns read_csv(const fs::path& p) {
  Columns c;
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  std::stringstream hs(line);
  for (std::string h; std::getline(hs, h, ',');) c.header.push_back(h);
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ls(line);
    for (std::string v; std::getline(ls, v, ',');) row.push_back(std::strtod(v.c_str(), nullptr));
    c.rows.push_back(row);
  }
  return c;
}

// configs/scenarios/NAME.yaml with each `from` replaced by its `to` (each must occur), written
// to a temporary file named for the tag and the process; throws std::runtime_error otherwise.
inline fs::path edited_scenario(const std::string& name, const std::string& tag,
                                const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = slurp(fs::path(HINF_SOURCE_DIR) / "configs" / "scenarios" / (name + ".yaml"));
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("not in the scenario: " + from);
    text.replace(at, from.size(), to);
  }
  const fs::path cfg = fs::temp_directory_path() / (name + "_" + tag + "_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(cfg) << text;
  return cfg;
}

// Each (from, to, key): configs/scenarios/NAME.yaml with `from` replaced by `to` exits 2, its
// message names `key`, and no summary.json is written.
using InvalidCase = std::tuple<std::string, std::string, std::string>;
inline void expect_invalid_values_exit_two(const std::string& family, const std::string& name,
                                           const std::vector<InvalidCase>& cases) {
  for (const auto& [from, to, key] : cases) {
    const fs::path cfg = edited_scenario(name, "bad", {{from, to}});
    const fs::path out = fresh_dir(family, "bad");
    const fs::path log = out.string() + ".log";
    EXPECT_EQ(run_scenario_file(cfg, "--quiet", out, log), 2) << to;
    const std::string message = slurp(log);
    EXPECT_NE(message.find(key), std::string::npos) << to << "\n" << message;
    EXPECT_FALSE(fs::exists(out / "summary.json")) << to;
    fs::remove(log);
    fs::remove(cfg);
  }
}

// configs/scenarios/NAME.yaml with `edits` (values that take the truth out of floating-point
// range) run with `args`: exit 4 (was: exit 0 with NaN rows), the message names the sample and
// the quantity (`expected`), and no run directory is written.
inline void expect_non_finite_truth_exit_four(const std::string& family, const std::string& name,
                                              const std::vector<std::pair<std::string, std::string>>& edits,
                                              const std::string& args, const std::string& expected) {
  const fs::path cfg = edited_scenario(name, "nonfinite", edits);
  const fs::path out = fresh_dir(family, "nonfinite");
  const fs::path log = out.string() + ".log";
  EXPECT_EQ(run_scenario_file(cfg, args + " --quiet", out, log), 4) << slurp(log);
  EXPECT_NE(slurp(log).find(expected), std::string::npos) << slurp(log);
  EXPECT_FALSE(fs::exists(out));
  fs::remove(log);
  fs::remove(cfg);
}

inline double metric_max(const YAML::Node& m) { return m.IsMap() ? m["max"].as<double>() : m.as<double>(); }
inline double metric_mean(const YAML::Node& m) { return m.IsMap() ? m["mean"].as<double>() : m.as<double>(); }
inline double metric_median(const YAML::Node& m) { return m.IsMap() ? m["median"].as<double>() : m.as<double>(); }

}  // namespace sim_cli_test
