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

}  // namespace hinf::sim
