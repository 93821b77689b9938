#include "hinf/common/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "hinf/common/error.hpp"

namespace hinf {
namespace {

namespace fs = std::filesystem;

// Attempts at a fresh temporary name before giving up (each one is O_EXCL).
constexpr int kTemporaryNameAttempts = 100;

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw Error(ErrorCode::InvalidInput, "cannot write '" + path + "': " + reason);
}

std::string directory_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

// The target's permission bits if it exists (it must be a regular file), else -1.
int existing_mode(const std::string& path) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return -1;
    fail(path, std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) fail(path, std::strerror(EISDIR));
  if (!S_ISREG(st.st_mode)) fail(path, "exists and is not a regular file (a device, pipe, socket or link is never replaced)");
  return static_cast<int>(st.st_mode & 07777);
}

// Creates a new temporary beside `path` exclusively; returns its descriptor and name.
int create_temporary(const std::string& path, std::string& name) {
  const fs::path p(path);
  const std::string stem = (fs::path(directory_of(path)) / ("." + p.filename().string() + ".tmp.")).string() +
                           std::to_string(::getpid()) + ".";
  for (int attempt = 0; attempt < kTemporaryNameAttempts; ++attempt) {
    name = stem + std::to_string(attempt);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) fail(path, "cannot create a temporary file in '" + directory_of(path) + "': " + std::strerror(errno));
  }
  fail(path, "no free temporary file name in '" + directory_of(path) + "'");
}

// Writes all of `content` to fd, then flushes it to disk; 0 or an errno value.
int write_all_and_sync(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t w = ::write(fd, content.data() + done, content.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(w);
  }
  return ::fsync(fd) == 0 ? 0 : errno;
}

std::string write_temporary(const std::string& path, const std::string& content) {
  const int mode = existing_mode(path);
  std::string name;
  const int fd = create_temporary(path, name);
  int err = write_all_and_sync(fd, content);
  if (err == 0 && mode >= 0 && ::fchmod(fd, static_cast<mode_t>(mode)) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) {
    ::unlink(name.c_str());
    fail(path, std::strerror(err));
  }
  return name;
}

void sync_directory(const std::string& path) {
  const int fd = ::open(directory_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // the rename is done; a directory that cannot be opened is not fatal
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void write_file_atomic(const std::string& path, const std::string& content, const std::vector<std::string>& inputs) {
  AtomicFileSet set;
  for (const std::string& in : inputs) set.protect(in);
  set.add(path, content);
  set.commit();
}

AtomicFileSet::~AtomicFileSet() {
  if (committed_) return;
  for (const Entry& e : entries_) ::unlink(e.temporary.c_str());
}

void AtomicFileSet::protect(const std::string& input) {
  struct stat st;
  if (::stat(input.c_str(), &st) == 0)
    inputs_.push_back({static_cast<unsigned long long>(st.st_dev), static_cast<unsigned long long>(st.st_ino), input});
}

void AtomicFileSet::refuse_input(const std::string& target) const {
  struct stat st;
  if (::stat(target.c_str(), &st) != 0) return;
  for (const FileId& in : inputs_)
    if (static_cast<unsigned long long>(st.st_dev) == in.device && static_cast<unsigned long long>(st.st_ino) == in.inode)
      fail(target, "it is the input file '" + in.path + "'; choose another output");
}

std::string AtomicFileSet::add(const std::string& path, const std::string& content) {
  refuse_input(path);
  entries_.push_back({write_temporary(path, content), path});
  return entries_.back().temporary;
}

std::string AtomicFileSet::reserve(const std::string& path) {
  refuse_input(path);
  entries_.push_back({write_temporary(path, std::string()), path});
  return entries_.back().temporary;
}

void AtomicFileSet::commit() {
  for (const Entry& e : entries_) {  // each still absent or a regular file, and no input
    existing_mode(e.target);
    refuse_input(e.target);
  }
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    if (std::rename(e.temporary.c_str(), e.target.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      for (std::size_t k = 0; k < i; ++k) ::unlink(entries_[k].target.c_str());
      for (std::size_t k = i; k < entries_.size(); ++k) ::unlink(entries_[k].temporary.c_str());
      committed_ = true;  // nothing left for the destructor
      fail(e.target, reason);
    }
  }
  for (const Entry& e : entries_) sync_directory(e.target);
  committed_ = true;
}

}  // namespace hinf
