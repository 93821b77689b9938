// Writing output files without ever leaving a partial one, in one place for every tool.
// A file is written to a temporary in its own directory (created exclusively, so a planted
// file or symlink is never followed), flushed to disk (fsync), renamed over the target
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

void write_file_atomic(const std::string& path, const std::string& content,
                       const std::vector<std::string>& inputs = {});

// Files that appear together: add() writes each one's complete temporary, commit()
// renames them all into place. Until commit() succeeds the destructor removes every
// temporary (a set never committed is a set of scoped scratch files); if a rename fails
// part-way, the files this commit already renamed are
// removed too (all or nothing).
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
  void commit();

 private:
  struct Entry {
    std::string temporary, target;
  };
  struct FileId {
    unsigned long long device, inode;
    std::string path;
  };
  void refuse_input(const std::string& target) const;
  std::vector<Entry> entries_;
  std::vector<FileId> inputs_;
  bool committed_ = false;
};

}  // namespace hinf
