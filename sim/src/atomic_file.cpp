#include "hinf/sim/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

namespace hinf::sim {

std::string temporary_path_for(const std::string& final_path) {
  // Unique per (final name, process, thread): a thread writes one file at a time.
  const std::filesystem::path p(final_path);
  const std::string name = "." + p.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                           std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()));
  return (p.parent_path() / name).string();
}

void commit_file(const std::string& temporary, const std::string& final_path) {
  if (std::rename(temporary.c_str(), final_path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw OutputError("cannot write '" + final_path + "': " + reason);
  }
}

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_path_for(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw OutputError("cannot write '" + path + "': cannot create '" + tmp + "': " + std::strerror(errno));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw OutputError("cannot write '" + path + "': write failed");
    }
  }
  commit_file(tmp, path);
}

}  // namespace hinf::sim
