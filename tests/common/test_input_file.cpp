// read_input_file (common/): regular files only, a cap per format, never a hang on a FIFO
// or an endless read of a device (issue 13, "readers with limits").
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_dir.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/input_file.hpp"

namespace {

namespace fs = std::filesystem;
using hinf::Error;
using hinf::ErrorCode;
using hinf::read_input_file;

using ScratchDir = hinf::test::ScratchDir;

// The message of the Error(InvalidInput) that reading `path` throws ("" if none).
std::string refusal(const std::string& path, std::size_t cap) {
  try {
    read_input_file(path, "config", cap);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    return e.what();
  }
  return "";
}

TEST(InputFile, ReadsTheExactBytesOfARegularFile) {
  ScratchDir dir("input_file");
  const std::string bytes("a: 1\n\0b\r\n", 9);
  std::ofstream(dir.path / "f.yaml", std::ios::binary) << bytes;
  EXPECT_EQ(read_input_file((dir.path / "f.yaml").string(), "config", 1024), bytes);
}

TEST(InputFile, RefusesWhatIsNotARegularFile) {
  ScratchDir dir("input_file");
  EXPECT_NE(refusal(dir.path.string(), 1024).find("it is a directory"), std::string::npos);
  EXPECT_NE(refusal("/dev/zero", 1024).find("it is a device"), std::string::npos);
  const fs::path fifo = dir.path / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Without a writer an ordinary open would block for ever.
  EXPECT_NE(refusal(fifo.string(), 1024).find("FIFO"), std::string::npos);
  const std::string missing = refusal((dir.path / "missing.yaml").string(), 1024);
  EXPECT_NE(missing.find("cannot read config '"), std::string::npos) << missing;
  EXPECT_NE(missing.find("No such file"), std::string::npos) << missing;
}

TEST(InputFile, RefusesAFileLargerThanTheCapBeforeReadingIt) {
  ScratchDir dir("input_file");
  const fs::path big = dir.path / "big.yaml";
  std::ofstream(big.string()).close();
  fs::resize_file(big, std::uintmax_t{1} << 40);  // 1 TiB, sparse: reading it would never end
  const std::string m = refusal(big.string(), hinf::kMaxConfigBytes);
  EXPECT_NE(m.find("1099511627776 bytes, more than the 16 MiB a config may have"), std::string::npos) << m;
}

}  // namespace
