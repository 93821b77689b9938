// Writing generated files: all-or-nothing. Every file is written to a temporary
// file in the target directory (same file system), and only when all of them are
// complete are they renamed into place. On failure the temporaries, and the
// directory if this call created it, are removed.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "hinf/synth/codegen.hpp"
#include "hinf/synth/status.hpp"

namespace hinf::synth {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw Error(ErrorCode::InvalidInput, "cannot write '" + path + "': " + what);
}

// Creates `path` exclusively (mode 0666 & ~umask) and writes `contents`.
// Returns 0 on success, else an errno value; a partly written file is removed.
int write_new_file(const std::string& path, const std::string& contents) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) return errno;
  int err = 0;
  std::size_t done = 0;
  while (done < contents.size()) {
    const ssize_t w = ::write(fd, contents.data() + done, contents.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      err = errno;
      break;
    }
    done += static_cast<std::size_t>(w);
  }
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) ::unlink(path.c_str());
  return err;
}

// Removes the listed files and, if set, the directory this call created.
struct Cleanup {
  std::vector<std::string> files;
  fs::path created_dir;
  bool armed = true;
  ~Cleanup() {
    if (!armed) return;
    std::error_code ec;
    for (const auto& f : files) fs::remove(f, ec);
    if (!created_dir.empty()) fs::remove_all(created_dir, ec);
  }
};

}  // namespace

void write_generated_files(const GeneratedFiles& files, const std::string& directory) {
  if (directory.empty()) fail(directory, "empty output directory");
  Cleanup cleanup;
  const fs::path dir(directory);
  std::error_code ec;
  const auto st = fs::status(dir, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) fail(directory, "exists and is not a directory");
  } else {
    // Remember the outermost directory created, to remove it on failure.
    fs::path first_missing = dir;
    for (fs::path p = dir.parent_path(); !p.empty() && !fs::exists(p, ec);
         p = p.parent_path()) {
      first_missing = p;
      if (p == p.parent_path()) break;
    }
    if (!fs::create_directories(dir, ec) || ec)
      fail(directory, "cannot create directory: " + ec.message());
    cleanup.created_dir = first_missing;
  }

  // 1. temporaries, named after the target so a leftover (after a crash) is obvious.
  std::vector<std::string> temps;
  for (const auto& f : files.files) {
    if (f.name.empty() || f.name.find('/') != std::string::npos)
      fail(f.name, "invalid generated file name");
    const std::string target = (dir / f.name).string();
    int err = EEXIST;
    for (int attempt = 0; attempt < 100 && err == EEXIST; ++attempt) {
      const std::string tmp = (dir / ("." + f.name + ".tmp" + std::to_string(::getpid()) +
                                      "-" + std::to_string(attempt)))
                                  .string();
      err = write_new_file(tmp, f.contents);
      if (err == 0) {
        temps.push_back(tmp);
        cleanup.files.push_back(tmp);
      }
    }
    if (err != 0) fail(target, std::strerror(err));
  }
  // 2. rename into place (atomic per file on POSIX).
  for (std::size_t i = 0; i < temps.size(); ++i) {
    const fs::path target = dir / files.files[i].name;
    fs::rename(temps[i], target, ec);
    if (ec) fail(target.string(), "cannot rename temporary file: " + ec.message());
    cleanup.files.push_back(target.string());  // all or nothing: undone on a later failure
  }
  cleanup.armed = false;
}

}  // namespace hinf::synth
