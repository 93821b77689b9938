// Step cost of the generated C filter (paper-sized: n = 6, m = 3, l = 6) against a
// hand-written plain C loop doing the same arithmetic (hand_loop.c), double and float.
// Before timing, the generated and hand-written steps are run side by side on the
// same inputs and must agree (they implement the same matrices), so the comparison
// is between equal work.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "bnav.h"
#include "bnavf.h"
#include "hand_loop.h"

namespace {

constexpr int kInputs = 1024;

template <class T>
std::array<std::array<T, 3>, kInputs> inputs() {
  std::mt19937_64 gen(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<std::array<T, 3>, kInputs> y{};
  for (auto& v : y)
    for (auto& e : v) e = static_cast<T>(u(gen));
  return y;
}

const auto kY = inputs<double>();
const auto kYf = inputs<float>();

// Generated and hand-written code must compute the same thing (else abort).
bool same_results() {
  bnav_state s{};
  bnavf_state sf{};
  double x[6] = {0}, z[6], zg[6];
  float xf[6] = {0}, zf[6], zgf[6];
  double worst = 0.0, worst_f = 0.0;
  for (int k = 0; k < 1000; ++k) {
    bnav_step(&s, kY[k % kInputs].data(), zg);
    hand_step(x, kY[k % kInputs].data(), z);
    bnavf_step(&sf, kYf[k % kInputs].data(), zgf);
    hand_step_f(xf, kYf[k % kInputs].data(), zf);
    for (int i = 0; i < 6; ++i) {
      worst = std::max(worst, std::abs(zg[i] - z[i]));
      worst_f = std::max(worst_f, static_cast<double>(std::abs(zgf[i] - zf[i])));
    }
  }
  std::printf("generated vs hand-written over 1000 steps: max |dz| double %.3g, float %.3g\n",
              worst, worst_f);
  return worst <= 1e-12 && worst_f <= 1e-5;
}

// The timed loop shared by every benchmark: step(y, z) on the inputs in turn.
template <class T, std::size_t NZ, class Step>
void time_steps(benchmark::State& state, const std::array<std::array<T, 3>, kInputs>& y, Step step) {
  T z[NZ];
  int k = 0;
  for (auto _ : state) {
    step(y[static_cast<std::size_t>(k)].data(), z);
    benchmark::DoNotOptimize(z);
    k = (k + 1) & (kInputs - 1);
  }
}

void BM_generated_double(benchmark::State& state) {
  bnav_state s{};
  time_steps<double, BNAV_NZ>(state, kY, [&s](const double* y, double* z) { bnav_step(&s, y, z); });
}
BENCHMARK(BM_generated_double);

void BM_hand_double(benchmark::State& state) {
  double x[6] = {0};
  time_steps<double, 6>(state, kY, [&x](const double* y, double* z) { hand_step(x, y, z); });
}
BENCHMARK(BM_hand_double);

void BM_generated_float(benchmark::State& state) {
  bnavf_state s{};
  time_steps<float, BNAVF_NZ>(state, kYf, [&s](const float* y, float* z) { bnavf_step(&s, y, z); });
}
BENCHMARK(BM_generated_float);

void BM_hand_float(benchmark::State& state) {
  float x[6] = {0};
  time_steps<float, 6>(state, kYf, [&x](const float* y, float* z) { hand_step_f(x, y, z); });
}
BENCHMARK(BM_hand_float);

}  // namespace

int main(int argc, char** argv) {
  if (!same_results()) {
    std::fprintf(stderr, "bench_codegen: generated and hand-written filters disagree\n");
    return 1;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
