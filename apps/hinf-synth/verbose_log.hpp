// The --verbose lines on stderr, and a watchdog that speaks when they fall silent.
//
// Some of a large solve's work reports nothing while it runs: MUMPS's factorisation of the
// Newton system inside Ipopt (~p³/3 multiply-adds, minutes at p ≈ 7000), the QR end game,
// the certificate. So that `-v` shows life within seconds at any size (issue 13, item 3),
// a thread prints "(still working …)" after kFirstQuietSeconds without a line, then at
// doubling intervals up to kLongestQuietSeconds, until the next real line. Every line goes
// through one lock, so the two threads never interleave within a line. If the thread
// cannot be created (ulimit -u), the log works without it and says so once.
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace hinf::cli {

class VerboseLog {
 public:
  // The first watchdog line comes after `first_quiet_s` without a line (tests shorten it).
  explicit VerboseLog(std::FILE* out, double first_quiet_s = kFirstQuietSeconds);
  ~VerboseLog();
  VerboseLog(const VerboseLog&) = delete;
  VerboseLog& operator=(const VerboseLog&) = delete;

  // A line (printf format, newline added) that restarts the silence clock.
  void line(const char* format, ...) __attribute__((format(printf, 2, 3)));
  // What the watchdog names as the work in progress ("phase 1, centring 0, Newton iteration 2").
  void set_activity(const std::string& what);

  static constexpr double kFirstQuietSeconds = 5.0;
  static constexpr double kLongestQuietSeconds = 60.0;

 private:
  using Clock = std::chrono::steady_clock;
  void watch();
  double seconds_since(Clock::time_point t) const;

  std::FILE* out_;
  const double first_quiet_s_;
  const Clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  Clock::time_point last_line_;
  double quiet_s_;
  std::string activity_;
  bool stop_ = false;
  std::thread watchdog_;
};

}  // namespace hinf::cli
