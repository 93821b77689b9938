// Monte-Carlo runs on a pool of std::threads. Run i uses the seed derive_seed(seed, i),
// so every run — and the whole result — is independent of the number of jobs and of
// the order in which the threads finish.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "hinf/sim/run.hpp"

namespace hinf::sim {

std::uint64_t run_seed(std::uint64_t seed, long run_index);

// Called after each finished run, serialised (never concurrently), with (done, total).
using ProgressCallback = std::function<void(long, long)>;

// Results in run-index order; run 0 keeps its trajectory. jobs ≥ 1 is an upper bound:
// threads the system refuses to create are left out (same result). If runs throw, the
// exception of the lowest-index failed run is rethrown after all threads have stopped.
// The pool itself: run(i) for every i in [0, runs), on at most `jobs` threads (the same
// contract: the lowest-index exception is rethrown after every thread has stopped). run(i)
// must write only to its own result slot. `interrupted` (may be empty) is polled before
// each run: once true, no run starts and SimulationError "interrupted" is thrown when the
// runs under way have ended (a front end's Ctrl-C).
void for_each_run(long runs, int jobs, const std::function<void(long)>& run, const ProgressCallback& progress,
                  const std::function<bool()>& interrupted = nullptr);

std::vector<RunResult> run_monte_carlo(const RunSetup& setup, long runs, std::uint64_t seed, int jobs,
                                       const ProgressCallback& progress,
                                       const std::function<bool()>& interrupted = nullptr);

// The seeds of runs 0 … runs − 1, in order: run_seed(seed, i).
std::vector<std::uint64_t> run_seeds(std::uint64_t seed, long runs);

// The Monte-Carlo runs of a scenario family: stats[i] = run_one(run_seed(seed, i),
// on_sample), where on_sample keeps filter f's samples of run 0 in (*samples)[f] when
// `samples` is given (sized by the caller) and is empty otherwise. for_each_run's contract.
template <class Stats, class Sample, class RunOne>
std::vector<std::vector<Stats>> run_family_campaign(long runs, int jobs, std::uint64_t seed,
                                                    std::vector<std::vector<Sample>>* samples, const RunOne& run_one,
                                                    const ProgressCallback& progress,
                                                    const std::function<bool()>& interrupted = nullptr) {
  std::vector<std::vector<Stats>> stats(static_cast<std::size_t>(runs));
  for_each_run(
      runs, jobs,
      [&](long i) {
        std::function<void(int, const Sample&)> on_sample;
        if (i == 0 && samples)
          on_sample = [samples](int f, const Sample& s) { (*samples)[static_cast<std::size_t>(f)].push_back(s); };
        stats[static_cast<std::size_t>(i)] = run_one(run_seed(seed, i), on_sample);
      },
      progress, interrupted);
  return stats;
}

}  // namespace hinf::sim
