// Writing output files without ever leaving a partial one, in one place for every tool.
// A file is written to a temporary in its own directory (created exclusively under a
// random name, so a planted file or symlink is never followed), flushed to disk (fsync), renamed over the target
// (atomic on POSIX file systems) and the directory is flushed. An existing target must be
// a regular file; its permission bits are kept; it is never one of the inputs given (the
// same file by device and inode, whatever the path). Every failure throws
// Error(InvalidInput) "cannot write 'PATH': REASON" with the system's reason. Callers'
// main() ignore SIGXFSZ, so that a file-size limit is an EFBIG error reported here
// (with the temporary removed) rather than a kill that leaves it behind.
#pragma once
#include <string>
#include <vector>

namespace hinf {

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove every live temporary of
// this process (AtomicFileSet's, and the previous files it keeps during a commit), then
// die of the signal as before. For the executables' main(); the set of live temporaries
// is the writer's one piece of process-wide state (a signal handler sees no other).
void remove_temporaries_on_signals();

void write_file_atomic(const std::string& path, const std::string& content,
                       const std::vector<std::string>& inputs = {});

// Files that appear together: add() writes each one's complete temporary, commit()
// renames them all into place. Until commit() succeeds the destructor removes every
// temporary (a set never committed is a set of scoped scratch files). commit() first
// keeps each existing target under a hard link; if a rename fails part-way, every
// target is put back as it was (the previous files restored, new ones removed): all or
// nothing.
class AtomicFileSet {
 public:
  AtomicFileSet() = default;
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;
  ~AtomicFileSet();

  // An input of the run: no target may be this file (checked by add(), reserve(), commit()).
  // A path that does not exist protects nothing.
  void protect(const std::string& input);

  // Returns the temporary's name (the file's content is readable there until commit()).
  std::string add(const std::string& path, const std::string& content);
  // A fresh empty temporary for `path` that another program fills (e.g. gnuplot's
  // output); returns its name. It is renamed by commit() like the others.
  std::string reserve(const std::string& path);
  // The targets added or reserved so far, in that order.
  std::vector<std::string> targets() const;
  void commit();

 private:
  struct Entry {
    std::string temporary, target;
    int slot = -1;              // in the signal handler's table
    std::string previous;       // hard link to the target's previous file, during commit()
    int previous_slot = -1;
  };
  struct FileId {
    unsigned long long device, inode;
    std::string path;
  };
  void refuse_input(const std::string& target) const;
  int keep_previous(Entry& e);
  void roll_back(std::size_t renamed);
  std::vector<Entry> entries_;
  std::vector<FileId> inputs_;
  bool committed_ = false;
};

}  // namespace hinf
