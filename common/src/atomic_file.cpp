#include "hinf/common/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "hinf/common/error.hpp"

namespace hinf {
namespace {

namespace fs = std::filesystem;

// Attempts at a fresh temporary name before giving up (each one is O_EXCL).
constexpr int kTemporaryNameAttempts = 100;

// ---- temporaries removed on SIGINT/SIGTERM/SIGHUP ------------------------------------
// A signal handler can only see process-wide state, so the live temporaries are kept in
// a fixed table of slots (no allocation, async-signal-safe reads): Free → Writing (the
// path is being copied) → Live (the handler unlinks it) → Free.
constexpr int kSlots = 256;
constexpr std::size_t kSlotPath = 4096;
enum SlotState : int { kFree = 0, kWriting = 1, kLive = 2 };
struct LiveTemporaries {
  std::atomic<int> state[kSlots];
  char path[kSlots][kSlotPath];
};
LiveTemporaries g_live{};  // the one piece of process-wide state of the writer

int register_temporary(const std::string& name) {
  if (name.size() >= kSlotPath) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!g_live.state[i].compare_exchange_strong(expected, kWriting)) continue;
    std::memcpy(g_live.path[i], name.c_str(), name.size() + 1);
    g_live.state[i].store(kLive);
    return i;
  }
  return -1;  // table full: this temporary is still removed on every failure, not on a signal
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_live.state[slot].store(kFree);
}

extern "C" void remove_temporaries_and_reraise(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_live.state[i].load() == kLive) ::unlink(g_live.path[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// A name nobody can predict: pid, a random 64-bit number and the attempt.
std::string random_suffix() {
  std::random_device device;
  const std::uint64_t r = (static_cast<std::uint64_t>(device()) << 32) ^ device();
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(r));
  return buf;
}

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

// Creates a new temporary beside `path` exclusively; returns its descriptor, name and
// signal slot. The name is registered for removal on a signal before the file exists, so
// no signal finds it unregistered (a name registered but not yet created is harmless: the
// handler's unlink fails).
int create_temporary(const std::string& path, std::string& name, int& slot) {
  const fs::path p(path);
  const std::string stem = (fs::path(directory_of(path)) / ("." + p.filename().string() + ".tmp.")).string() +
                           std::to_string(::getpid()) + "." + random_suffix() + ".";
  for (int attempt = 0; attempt < kTemporaryNameAttempts; ++attempt) {
    name = stem + std::to_string(attempt);
    slot = register_temporary(name);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd >= 0) return fd;
    const int err = errno;
    unregister_temporary(slot);  // not ours
    slot = -1;
    if (err != EEXIST) fail(path, "cannot create a temporary file in '" + directory_of(path) + "': " + std::strerror(err));
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

std::string write_temporary(const std::string& path, const std::string& content, int& slot) {
  const int mode = existing_mode(path);
  std::string name;
  const int fd = create_temporary(path, name, slot);
  int err = write_all_and_sync(fd, content);
  if (err == 0 && mode >= 0 && ::fchmod(fd, static_cast<mode_t>(mode)) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) {
    ::unlink(name.c_str());
    unregister_temporary(slot);
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

void remove_temporaries_on_signals() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, remove_temporaries_and_reraise);
}

void write_file_atomic(const std::string& path, const std::string& content, const std::vector<std::string>& inputs) {
  AtomicFileSet set;
  for (const std::string& in : inputs) set.protect(in);
  set.add(path, content);
  set.commit();
}

AtomicFileSet::~AtomicFileSet() {
  for (const Entry& e : entries_) {
    if (!committed_) ::unlink(e.temporary.c_str());
    unregister_temporary(e.slot);
  }
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
  int slot = -1;
  const std::string temporary = write_temporary(path, content, slot);
  entries_.push_back({temporary, path, slot, std::string(), -1});
  return temporary;
}

std::string AtomicFileSet::reserve(const std::string& path) { return add(path, std::string()); }

std::vector<std::string> AtomicFileSet::targets() const {
  std::vector<std::string> out;
  for (const Entry& e : entries_) out.push_back(e.target);
  return out;
}

// Before the renames, each existing target gets a hard link under a fresh name, so that
// a rename failing part-way can put every previous file back (all or nothing, also for
// the files this commit had already replaced). 0 or an errno value.
int AtomicFileSet::keep_previous(Entry& e) {
  if (existing_mode(e.target) < 0) return 0;
  for (int attempt = 0; attempt < kTemporaryNameAttempts; ++attempt) {
    const std::string name = e.temporary + ".old" + std::to_string(attempt);
    if (::link(e.target.c_str(), name.c_str()) == 0) {
      e.previous = name;
      e.previous_slot = register_temporary(name);
      return 0;
    }
    if (errno != EEXIST) return errno;
  }
  return EEXIST;
}

void AtomicFileSet::roll_back(std::size_t renamed) {
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    Entry& e = entries_[k];
    if (k < renamed) {
      if (e.previous.empty()) ::unlink(e.target.c_str());
      else std::rename(e.previous.c_str(), e.target.c_str());
    } else {
      ::unlink(e.temporary.c_str());
      if (!e.previous.empty()) ::unlink(e.previous.c_str());
    }
    unregister_temporary(e.previous_slot);
  }
  committed_ = true;  // nothing left for the destructor
}

void AtomicFileSet::commit() {
  for (const Entry& e : entries_) {  // each still absent or a regular file, and no input
    existing_mode(e.target);
    refuse_input(e.target);
  }
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (const int err = keep_previous(entries_[i])) {
      const std::string reason = std::strerror(err);
      roll_back(0);
      fail(entries_[i].target, "cannot keep the previous file while the new set is renamed: " + reason);
    }
  }
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    if (std::rename(e.temporary.c_str(), e.target.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      roll_back(i);
      fail(e.target, reason + " (no file of the set was changed)");
    }
  }
  for (Entry& e : entries_) {
    if (!e.previous.empty()) ::unlink(e.previous.c_str());
    unregister_temporary(e.previous_slot);
    e.previous_slot = -1;
  }
  for (const Entry& e : entries_) sync_directory(e.target);
  committed_ = true;
}

}  // namespace hinf
