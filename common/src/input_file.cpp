// read_input_file (input_file.hpp).
#include "hinf/common/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "hinf/common/error.hpp"

namespace hinf {
namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& what, const std::string& why) {
  throw Error(ErrorCode::InvalidInput, "cannot read " + what + " '" + path + "': " + why);
}

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "it is a directory";
  if (S_ISFIFO(mode)) return "it is a FIFO (pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "it is a device, not a regular file";
  if (S_ISSOCK(mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

// The first bytes of a level-5 MAT-file's header (the tools write them with --format mat).
constexpr const char* kMatFileMagic = "MATLAB 5.0 MAT-file";

std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// Closes the descriptor on every path out of read_input_file.
struct Descriptor {
  int fd;
  ~Descriptor() { ::close(fd); }
};

}  // namespace

std::string read_input_file(const std::string& path, const std::string& what, std::size_t max_bytes) {
  // O_NONBLOCK: opening a FIFO without a writer must not block; it is refused below.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) refuse(path, what, std::strerror(errno));
  const Descriptor closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) refuse(path, what, std::strerror(errno));
  if (!S_ISREG(st.st_mode)) refuse(path, what, kind_of(st.st_mode));
  if (static_cast<std::size_t>(st.st_size) > max_bytes)
    refuse(path, what, std::to_string(st.st_size) + " bytes, more than the " + mib(max_bytes) + " a " + what +
                           " may have");
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) refuse(path, what, std::string("read error: ") + std::strerror(errno));
    if (got == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(got));
    if (bytes.size() > max_bytes)  // the file grew while it was read
      refuse(path, what, "more than the " + mib(max_bytes) + " a " + what + " may have");
  }
  if (bytes.rfind(kMatFileMagic, 0) == 0)
    refuse(path, what, "it is a MATLAB file (written with --format mat); give the YAML file");
  return bytes;
}

}  // namespace hinf
