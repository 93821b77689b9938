// Writing generated files: all-or-nothing, by one AtomicFileSet (hinf/common/atomic_file.hpp).
// On failure the directory, if this call created it, is removed.

#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "hinf/codegen/codegen.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/common/error.hpp"

namespace hinf::codegen {
namespace {

namespace fs = std::filesystem;

// The line of the leading comment that names the prefix (emit_c.cpp's provenance).
constexpr const char* kPrefixMarker = " * Prefix: ";

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

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The prefix recorded in a file this generator wrote (" * Prefix: NAME" in its leading
// comment), or "" for any other file.
std::string recorded_prefix(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  for (int i = 0; i < 12 && std::getline(in, line); ++i) {
    if (i == 0 && line.rfind("/* ", 0) != 0) return "";
    if (line.rfind(kPrefixMarker, 0) == 0) return line.substr(std::strlen(kPrefixMarker));
  }
  return "";
}

// Refuses to write `files` into `dir` where a file generated there for another prefix
// would be replaced (nav_vectors.h of prefix 'nav' by prefix 'nav_vectors'), or where
// such a prefix differs from ours only in case ('nav' and 'Nav').
void check_other_prefixes(const GeneratedFiles& files, const fs::path& dir) {
  std::set<std::string> ours;
  for (const auto& f : files.files) ours.insert(lower(f.name));
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    const std::string theirs = recorded_prefix(entry.path());
    if (theirs.empty() || theirs == files.prefix) continue;
    if (lower(theirs) == lower(files.prefix))
      fail(entry.path().string(), "generated for prefix '" + theirs + "', which differs from '" + files.prefix +
                                      "' only in case: the two filters would share their macros and include "
                                      "guards, and one file name on a case-insensitive file system; choose "
                                      "another prefix");
    if (ours.count(lower(entry.path().filename().string())) != 0)
      fail(entry.path().string(), "generated for prefix '" + theirs + "'; prefix '" + files.prefix +
                                      "' would replace it (choose another prefix or directory)");
  }
}

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

  check_other_prefixes(files, dir);
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
