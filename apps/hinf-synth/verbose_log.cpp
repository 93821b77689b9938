// VerboseLog (verbose_log.hpp).
#include "verbose_log.hpp"

#include <algorithm>
#include <cstdarg>
#include <system_error>

namespace hinf::cli {

VerboseLog::VerboseLog(std::FILE* out, double first_quiet_s)
    : out_(out), first_quiet_s_(first_quiet_s), start_(Clock::now()), last_line_(start_), quiet_s_(first_quiet_s) {
  try {
    watchdog_ = std::thread([this] { watch(); });
  } catch (const std::system_error& e) {
    std::fprintf(out_, "(no watchdog thread: %s; lines come only from the solver)\n", e.what());
  }
}

VerboseLog::~VerboseLog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (watchdog_.joinable()) watchdog_.join();
}

double VerboseLog::seconds_since(Clock::time_point t) const {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

void VerboseLog::line(const char* format, ...) {
  std::lock_guard<std::mutex> lock(mutex_);
  va_list args;
  va_start(args, format);
  std::vfprintf(out_, format, args);
  va_end(args);
  std::fputc('\n', out_);
  std::fflush(out_);
  last_line_ = Clock::now();
  quiet_s_ = first_quiet_s_;
}

void VerboseLog::set_activity(const std::string& what) {
  std::lock_guard<std::mutex> lock(mutex_);
  activity_ = what;
}

void VerboseLog::watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  // when the watchdog speaks next: quiet_s_ after the last line (both move under the lock)
  const auto due = [this] {
    return last_line_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(quiet_s_));
  };
  while (!stop_) {
    if (wake_.wait_until(lock, due(), [this] { return stop_; })) return;
    if (Clock::now() < due()) continue;  // a line came meanwhile
    std::fprintf(out_, "      (still working%s%s: %.1f s in all)\n", activity_.empty() ? "" : " after ",
                 activity_.c_str(), seconds_since(start_));
    std::fflush(out_);
    quiet_s_ = std::min(2 * quiet_s_, std::max(kLongestQuietSeconds, first_quiet_s_));
    last_line_ = Clock::now();
  }
}

}  // namespace hinf::cli
