// What the API tests (test_simulation_api.cpp, test_synthesis_api.cpp) share: a file's bytes,
// and text with its timing lines removed ("timing apart", as scripts/output-digest compares
// outputs).
#pragma once
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace hinf::test {

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

inline std::string timing_apart(const std::string& text) {
  static const std::regex timing("solve_time_s|wall_s|elapsed|_seconds");
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line))
    if (!std::regex_search(line, timing)) out += line + "\n";
  return out;
}

}  // namespace hinf::test
