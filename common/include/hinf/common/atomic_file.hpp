// Writing output files without ever leaving a partial one, in one place for every tool.
// A file is written to a temporary in its own directory (created exclusively, so a planted
// file or symlink is never followed), flushed to disk (fsync), renamed over the target
// (atomic on POSIX file systems) and the directory is flushed. An existing target must be
// a regular file; its permission bits are kept. Every failure throws
// Error(InvalidInput) "cannot write 'PATH': REASON" with the system's reason.
#pragma once
#include <string>
#include <vector>

namespace hinf {

void write_file_atomic(const std::string& path, const std::string& content);

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
  std::vector<Entry> entries_;
  bool committed_ = false;
};

}  // namespace hinf
