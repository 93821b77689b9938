// bench_gps_ins_campaign [p] [runs]: the fly-around (sim/gps_ins_scenario.hpp defaults) with
// products of inertia p (default 0), `runs` runs (default 20) of 10 000 s, the three filters
// of configs/scenarios/gps-ins-flyaround.yaml — the EKF (p_f = 0), the REKF with p_f = 0.03
// and with p_f = 0.3 — on each run's one measurement stream, one thread. Prints, per
// filter, the median over runs of the window (4000–10 000 s) maximum of each error (largest
// component), the mean NEES, the γ-condition violations, and the wall time.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "hinf/sim/gps_ins_run.hpp"

using namespace hinf::sim;

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
}
}  // namespace

int main(int argc, char** argv) {
  GpsInsScenario s;
  s.inertia_products_fraction = argc > 1 ? std::atof(argv[1]) : 0.0;
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 20;
  GpsInsFilterSettings ekf, rekf, rekf_p30;
  rekf.name = "rekf";
  rekf.kind = GpsInsFilterKind::Rekf;
  rekf.inertia_uncertainty_fraction = 0.03;
  rekf_p30 = rekf;
  rekf_p30.name = "rekf_p30";
  rekf_p30.inertia_uncertainty_fraction = 0.3;
  const std::vector<GpsInsFilterSettings> filters{ekf, rekf, rekf_p30};
  const std::size_t n = filters.size();
  std::vector<std::vector<double>> pos(n), vel(n), att(n), rate(n), bias(n);
  std::vector<double> nees(n, 0.0);
  std::vector<long> violations(n, 0), diverged(n, 0);
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < runs; ++r) {
    const auto st = run_gps_ins(s, filters, GpsInsRunOptions{}, 1000 + r);
    for (std::size_t i = 0; i < n; ++i) {
      pos[i].push_back(st[i].position_max.maxCoeff());
      vel[i].push_back(st[i].velocity_max.maxCoeff());
      att[i].push_back(st[i].attitude_max.maxCoeff());
      rate[i].push_back(st[i].rate_max.maxCoeff());
      bias[i].push_back(st[i].bias_max.maxCoeff());
      nees[i] += st[i].nees_mean / runs;
      violations[i] += st[i].gamma_violations;
      diverged[i] += st[i].diverged;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t i = 0; i < n; ++i)
    std::printf("%-8s p=%.2f median of window max: position %.4g m, velocity %.4g m/s, attitude %.4g deg, "
                "rate %.4g deg/s, bias %.4g deg/s; mean NEES %.4g; gamma violations %ld; diverged %ld\n",
                filters[i].name.c_str(), s.inertia_products_fraction, median(pos[i]), median(vel[i]), median(att[i]),
                median(rate[i]), median(bias[i]), nees[i], violations[i], diverged[i]);
  std::printf("%d runs x %.0f s, %zu filters, one thread: %.2f s\n", runs, s.duration, n, seconds);
  return 0;
}
