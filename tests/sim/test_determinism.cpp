// Reproducibility: same seed → same output, whatever the number of jobs; run i depends
// only on (seed, i).
#include <gtest/gtest.h>

#include "hinf/sim/monte_carlo.hpp"
#include "hinf/sim/report.hpp"
#include "hinf/sim/scenario_yaml.hpp"

namespace {

using namespace hinf::sim;

RunSetup small_setup() {
  RunSetup setup;
  setup.scenario = parse_scenario(R"(
duration: 60
truth: {delta: 0.03, initial_state: [600, 550, 1040, 0.02, -0.08, 0.03]}
control:
  law: state_feedback
  K: [[-2.2541, -0.0071, -0.0072, -22.3975, 2.3256, 1.9369],
      [-0.0104, -2.2493, -0.0055, 2.3259, -23.7456, 1.4544],
      [-0.0072, -0.0055, -2.2471, 1.9357, 1.4552, -24.2818]]
process_noise: [{type: gaussian, sigma: 1e-4}, {type: gauss_markov, sigma: 1e-5, time_constant: 50}]
measurement:
  range: [{type: student_t, sigma: 0.1, dof: 4}, {type: impulsive, probability: 0.01, magnitude: 1}]
  azimuth: {type: laplace, sigma: 7.5e-5}
  elevation: {type: uniform, sigma: 7.5e-5}
filters: {ekf: {}, ekf_no_control: {}, rekf: {}}
)",
                                  "/tmp/determinism.yaml");
  // The published gains of docs/maths.md (78)–(80) as the LTI filter (no file needed).
  LtiGains g;
  g.A_F.resize(6, 6);
  g.A_F << -0.6126, -0.0053, -0.0046, 0.1, -1.7e-6, -1.0e-6, -0.0052, -0.6083, -0.0035, -1.5e-6, 0.1, -1.4e-6,
      -0.0046, -0.0035, -0.6066, -1.5e-6, -5.6e-7, 0.1, -6.1302, -0.0390, -0.0337, 0.9980, 1.1e-4, 8.2e-5, -0.0385,
      -6.0991, -0.0259, 8.0e-5, 0.9979, 6.3e-5, -0.0337, -0.0259, -6.0864, 8.3e-5, 6.4e-5, 0.9979;
  g.B_F.resize(6, 3);
  g.B_F << -1.6126, -0.0053, -0.0046, -0.0052, -1.6083, -0.0035, -0.0046, -0.0035, -1.6066, -6.1300, -0.0390, -0.0337,
      -0.0385, -6.0989, -0.0259, -0.0337, -0.0259, -6.0862;
  g.C_F = -Eigen::MatrixXd::Identity(6, 6);
  setup.hinf = g;
  setup.scenario.filters.hinf = LtiGainsSource{"(inline)", ""};
  return setup;
}

TEST(Determinism, IndependentOfJobs) {
  const RunSetup setup = small_setup();
  SummaryContext ctx;
  ctx.seed = 5;
  const auto r1 = run_monte_carlo(setup, 6, 5, 1, nullptr);
  const auto r2 = run_monte_carlo(setup, 6, 5, 2, nullptr);
  const auto r3 = run_monte_carlo(setup, 6, 5, 5, nullptr);
  EXPECT_EQ(format_runs_csv(r1), format_runs_csv(r2));
  EXPECT_EQ(format_runs_csv(r1), format_runs_csv(r3));
  EXPECT_EQ(format_summary_json(setup.scenario, r1, ctx), format_summary_json(setup.scenario, r3, ctx));
  ASSERT_TRUE(r1[0].trajectory && r3[0].trajectory);
  EXPECT_EQ(format_trajectory_csv(*r1[0].trajectory), format_trajectory_csv(*r3[0].trajectory));
  // the runs differ from each other (the seeds are used)
  EXPECT_NE(r1[0].filters[0].metrics.position_rms_m, r1[1].filters[0].metrics.position_rms_m);
}

TEST(Determinism, RunDependsOnlyOnSeedAndIndex) {
  const RunSetup setup = small_setup();
  const auto batch = run_monte_carlo(setup, 4, 11, 2, nullptr);
  const RunResult single = simulate_run(setup, run_seed(11, 3), true);
  EXPECT_EQ(format_runs_csv({batch[3]}), format_runs_csv({single}));
  const auto other = run_monte_carlo(setup, 1, 12, 1, nullptr);
  EXPECT_NE(format_trajectory_csv(*other[0].trajectory), format_trajectory_csv(*batch[0].trajectory));
}

TEST(Determinism, EveryFilterProducesFiniteMetrics) {
  const RunSetup setup = small_setup();
  const auto r = run_monte_carlo(setup, 1, 1, 1, nullptr);
  ASSERT_EQ(r[0].filters.size(), 4u);
  for (const auto& f : r[0].filters) {
    EXPECT_FALSE(f.metrics.diverged) << f.name;
    ASSERT_TRUE(f.metrics.position_rms_m.has_value()) << f.name;
    EXPECT_TRUE(std::isfinite(*f.metrics.position_rms_m)) << f.name;
  }
}

}  // namespace
