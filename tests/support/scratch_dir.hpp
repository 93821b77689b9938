// A fresh temporary directory for one test, removed with everything in it.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>

namespace hinf::test {

struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(const std::string& tag)
      : path(std::filesystem::temp_directory_path() / ("hinf_" + tag + "_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::string operator/(const char* name) const { return (path / name).string(); }
  int entries() const {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(path)) n += e.exists() ? 1 : 0;
    return n;
  }
};

}  // namespace hinf::test
