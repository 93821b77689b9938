// solve -v's VerboseLog (apps/hinf-synth/verbose_log.hpp): its watchdog speaks when the
// solver has been silent, naming the work in progress, and stays quiet otherwise; lines
// come out whole. The quiet period is shortened to 50 ms; no assertion depends on how
// fast the machine is beyond "0.6 s is longer than 50 ms".
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "verbose_log.hpp"

namespace {

std::string read_all(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  char buf[4096];
  size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, got);
  return s;
}

int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

TEST(VerboseLog, SpeaksAfterSilenceNamingTheWork) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    hinf::cli::VerboseLog log(f, 0.05);
    log.line("size line %d", 42);
    log.set_activity("phase 1, centring 0, Newton iteration 1");
    std::this_thread::sleep_for(std::chrono::milliseconds(600));
  }
  const std::string out = read_all(f);
  std::fclose(f);
  EXPECT_EQ(out.rfind("size line 42\n", 0), 0u) << out;
  // 50, 100, 200 ms after the last line: at least one, and the intervals double, so at
  // most 4 within 0.6 s (5 would need the machine to report time running backwards)
  const int watchdog_lines = count(out, "(still working after phase 1, centring 0, Newton iteration 1: ");
  EXPECT_GE(watchdog_lines, 1) << out;
  EXPECT_LE(watchdog_lines, 4) << out;
  EXPECT_EQ(count(out, "\n"), 1 + watchdog_lines) << out;  // every line whole
}

TEST(VerboseLog, QuietWhileLinesKeepComing) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    hinf::cli::VerboseLog log(f, 3600.0);  // never due within the test
    for (int i = 0; i < 100; ++i) log.line("line %d", i);
  }  // the destructor wakes the watchdog and joins it at once (or the test times out)
  const std::string out = read_all(f);
  std::fclose(f);
  EXPECT_EQ(count(out, "\n"), 100);
  EXPECT_EQ(count(out, "still working"), 0);
  EXPECT_NE(out.find("line 99\n"), std::string::npos);
}

}  // namespace
