// load_config: reading a config file's exact bytes (their SHA-256 goes into the output).
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>
#include <filesystem>

#include "hinf/synth/config.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {
namespace {

// A config is a few kilobytes; refuse to read without bound (e.g. /dev/zero).
constexpr std::streamsize kMaxConfigBytes = 64 << 20;

}  // namespace

SynthConfig load_config(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorCode::InvalidInput, "cannot read config '" + path + "': it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error(ErrorCode::InvalidInput, "cannot open config '" + path + "': " +
                                             (errno ? std::strerror(errno) : "unknown error"));
  std::string bytes;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    bytes.append(buffer, static_cast<size_t>(in.gcount()));
    if (static_cast<std::streamsize>(bytes.size()) > kMaxConfigBytes)
      throw Error(ErrorCode::InvalidInput, "cannot read config '" + path + "': larger than " +
                                               std::to_string(kMaxConfigBytes >> 20) + " MiB");
  }
  if (in.bad())
    throw Error(ErrorCode::InvalidInput, "cannot read config '" + path + "': read error");
  if (bytes.empty())
    throw Error(ErrorCode::InvalidInput, path + ": empty config file (0 bytes)");
  return parse_config(bytes, path);
}

}  // namespace hinf::synth
