// Writing generated files: all-or-nothing, by one AtomicFileSet (hinf/common/atomic_file.hpp).
// On failure the directory, if this call created it, is removed.

#include <filesystem>
#include <string>
#include <vector>

#include "hinf/codegen/codegen.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/common/error.hpp"

namespace hinf::codegen {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw Error(ErrorCode::InvalidInput, "cannot write '" + path + "': " + what);
}

// Removes the directory this call created unless disarmed.
struct CreatedDirectory {
  fs::path path;
  bool armed = true;
  ~CreatedDirectory() {
    std::error_code ec;
    if (armed && !path.empty()) fs::remove_all(path, ec);
  }
};

}  // namespace

void write_generated_files(const GeneratedFiles& files, const std::string& directory,
                           const std::vector<std::string>& inputs) {
  if (directory.empty()) fail(directory, "empty output directory");
  CreatedDirectory created;
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
    created.path = first_missing;
  }

  // All files appear together or not at all (hinf/common/atomic_file.hpp).
  AtomicFileSet set;
  for (const std::string& in : inputs) set.protect(in);
  for (const auto& f : files.files) {
    if (f.name.empty() || f.name.find('/') != std::string::npos) fail(f.name, "invalid generated file name");
    set.add((dir / f.name).string(), f.contents);
  }
  set.commit();
  created.armed = false;
}

}  // namespace hinf::codegen
