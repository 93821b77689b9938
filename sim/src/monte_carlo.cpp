#include "hinf/sim/monte_carlo.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>

#include "hinf/sim/rng.hpp"
#include "hinf/sim/simulation_error.hpp"

namespace hinf::sim {

std::uint64_t run_seed(std::uint64_t seed, long run_index) {
  return derive_seed(seed, static_cast<std::uint64_t>(run_index));
}

std::vector<std::uint64_t> run_seeds(std::uint64_t seed, long runs) {
  std::vector<std::uint64_t> seeds;
  for (long i = 0; i < runs; ++i) seeds.push_back(run_seed(seed, i));
  return seeds;
}

std::vector<RunResult> run_monte_carlo(const RunSetup& setup, long runs, std::uint64_t seed, int jobs,
                                       const ProgressCallback& progress, const std::function<bool()>& interrupted) {
  std::vector<RunResult> results(static_cast<std::size_t>(runs));
  for_each_run(
      runs, jobs,
      [&](long i) { results[static_cast<std::size_t>(i)] = simulate_run(setup, run_seed(seed, i), i == 0); },
      progress, interrupted);
  return results;
}

void for_each_run(long runs, int jobs, const std::function<void(long)>& run, const ProgressCallback& progress,
                  const std::function<bool()>& interrupted) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(runs));
  std::atomic<long> next{0};
  std::atomic<bool> failed{false};
  std::atomic<bool> stopped{false};
  std::mutex poll_mutex;  // the poll is called from one thread at a time
  const auto stop_requested = [&] {
    if (!interrupted) return false;
    std::lock_guard<std::mutex> lock(poll_mutex);
    if (!stopped.load() && interrupted()) stopped.store(true);
    return stopped.load();
  };
  std::mutex progress_mutex;
  long done = 0;

  auto worker = [&]() {
    for (;;) {
      if (stop_requested()) return;
      const long i = next.fetch_add(1);
      if (i >= runs || failed.load()) return;
      try {
        run(i);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
        failed.store(true);
      }
      std::lock_guard<std::mutex> lock(progress_mutex);
      ++done;
      if (progress) progress(done, runs);
    }
  };
  const int n_threads = static_cast<int>(std::min<long>(std::max(1, jobs), std::max<long>(1, runs)));
  std::vector<std::thread> threads;
  threads.reserve(static_cast<std::size_t>(n_threads));
  // A thread the system cannot create (address space, process limit) is simply not added:
  // the threads already running, and this one, share the runs (every run's seed depends
  // on its index only, so the result is the same).
  for (int j = 1; j < n_threads; ++j) {
    try {
      threads.emplace_back(worker);
    } catch (const std::system_error&) {
      break;
    }
  }
  worker();
  for (auto& t : threads) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  if (stopped.load()) throw SimulationError("interrupted: " + std::to_string(done) + " of " + std::to_string(runs) +
                                            " runs done");
}

}  // namespace hinf::sim
