// A continuous-time controller flown at a period T (docs/maths.md (161)–(161c)): the plant at
// the sample instants against a fine Runge–Kutta integration with w and u held, the controller's
// zero-order hold against its closed form, the sampled loop's γ against the continuous loop's as
// T shrinks, and the discretise job's refusals and files (read back by verify).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <random>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/runtime_yaml/controller_file.hpp"
#include "hinf/synth/api.hpp"
#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/sampled_loop.hpp"
#include "random_plants.hpp"
#include "scratch_dir.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using hinf::synth::ControllerSampling;

const std::string kSampledLoopConfig = std::string(HINF_SOURCE_DIR) + "/tests/data/controllers/double-integrator.yaml";

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The continuous design of kSampledLoopConfig, written to dir/k.yaml; its path.
std::string continuous_design(const hinf::test::ScratchDir& dir) {
  const std::string path = dir / "k.yaml";
  write_text(path, hinf::synth::load_problem(kSampledLoopConfig)->solve().file);
  return path;
}

// ẋ = A x + B1 w + B2 u over one sample with w and u held: classical RK4 in `steps` steps.
VectorXd rk4_held_sample(const hinf::GeneralisedPlant& P, VectorXd x, const VectorXd& w, const VectorXd& u, double T,
                   int steps) {
  const double h = T / steps;
  const VectorXd f0 = P.B1 * w + P.B2 * u;
  const auto f = [&](const VectorXd& s) -> VectorXd { return P.A * s + f0; };
  for (int i = 0; i < steps; ++i) {
    const VectorXd k1 = f(x), k2 = f(x + h / 2 * k1), k3 = f(x + h / 2 * k2), k4 = f(x + h * k3);
    x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return x;
}

TEST(SampledLoop, PlantAtTheSampleInstantsMatchesAFineIntegration) {
  std::mt19937 g(7);
  hinf::GeneralisedPlant P;
  P.A = hinf::test::random_matrix(g, 3, 3);
  P.B1 = hinf::test::random_matrix(g, 3, 2);
  P.B2 = hinf::test::random_matrix(g, 3, 1);
  P.C1 = hinf::test::random_matrix(g, 2, 3);
  P.C2 = hinf::test::random_matrix(g, 1, 3);
  P.D11 = MatrixXd::Zero(2, 2);
  P.D12 = hinf::test::random_matrix(g, 2, 1);
  P.D21 = hinf::test::random_matrix(g, 1, 2);
  const double T = 0.2;
  const hinf::GeneralisedPlant D = hinf::synth::sample_generalised_plant(P, T, "--zoh");
  EXPECT_EQ(D.time, hinf::TimeDomain::Discrete);
  EXPECT_EQ(D.sample_time, T);
  EXPECT_EQ(D.C1, P.C1);
  EXPECT_EQ(D.C2, P.C2);
  EXPECT_EQ(D.D12, P.D12);
  EXPECT_EQ(D.D21, P.D21);
  VectorXd x = hinf::test::random_vector(g, 3), xd = x;
  for (int k = 0; k < 5; ++k) {
    const VectorXd w = hinf::test::random_vector(g, 2), u = hinf::test::random_vector(g, 1);
    x = rk4_held_sample(P, x, w, u, T, 2000);
    xd = D.A * xd + D.B1 * w + D.B2 * u;
    EXPECT_LT((x - xd).norm(), 1e-11 * (1 + x.norm())) << "sample " << k;
  }
}

TEST(SampledLoop, ControllerZeroOrderHoldClosedFormAndTustinIsTheRule) {
  hinf::Controller K{MatrixXd::Constant(1, 1, -3), MatrixXd::Constant(1, 1, 2), MatrixXd::Constant(1, 1, 1.5),
                     MatrixXd::Constant(1, 1, 0.5)};
  const double T = 0.05;
  const hinf::Controller z = hinf::synth::sample_controller(K, T, ControllerSampling::ZeroOrderHold);
  EXPECT_NEAR(z.A_K(0, 0), std::exp(-3 * T), 1e-15);
  EXPECT_NEAR(z.B_K(0, 0), 2 * (1 - std::exp(-3 * T)) / 3, 1e-15);
  EXPECT_EQ(z.C_K, K.C_K);
  EXPECT_EQ(z.D_K, K.D_K);
  const hinf::Controller t = hinf::synth::sample_controller(K, T, ControllerSampling::Tustin);
  const hinf::Controller r = hinf::tustin(K, T);
  EXPECT_EQ(t.A_K, r.A_K);
  EXPECT_EQ(t.D_K, r.D_K);
}

TEST(SampledLoop, GammaTendsToTheContinuousLoopsAsTheSampleShrinks) {
  const hinf::test::ScratchDir dir("sampled_gamma");
  const std::string k = continuous_design(dir);
  const auto problem = hinf::synth::load_problem(kSampledLoopConfig);
  const double gamma_c = *hinf::runtime_yaml::load_controller_file(k).gamma;
  for (ControllerSampling m : {ControllerSampling::Tustin, ControllerSampling::ZeroOrderHold}) {
    double last = INFINITY;
    for (double T : {0.1, 0.01, 0.001}) {
      const hinf::synth::DiscretiseOutcome d = problem->discretise(k, T, m);
      ASSERT_TRUE(d.holds) << d.report;
      const double gap = std::abs(d.gamma / gamma_c - 1);
      EXPECT_LT(gap, last) << to_string(m) << " T = " << T;
      last = gap;
      // the file states the sampled loop's γ, and its discrete controller is the rule's
      const auto f = hinf::runtime_yaml::parse_controller_yaml(d.file, "discretised");
      EXPECT_TRUE(f.discrete);
      EXPECT_EQ(*f.sample_time, T);
      EXPECT_EQ(*f.gamma, d.gamma);
      ASSERT_TRUE(f.discretised.has_value());
      EXPECT_EQ(f.discretised->method, to_string(m));
      EXPECT_EQ(*f.discretised->continuous_gamma, gamma_c);
    }
    EXPECT_LT(last, 5e-3) << to_string(m);  // T = 1 ms: within 0.5 % of the continuous loop
  }
}

// σ_max of the discrete loop (A, B, C, D) at e^{jθ}, by a dense complex LU (independent of
// certify's frequency response and pencil).
double sampled_sigma(const hinf::StateSpace& G, double theta) {
  using cd = std::complex<double>;
  Eigen::MatrixXcd M = -G.A.cast<cd>();
  M.diagonal().array() += std::polar(1.0, theta);
  const Eigen::MatrixXcd H = G.C.cast<cd>() * M.partialPivLu().solve(G.B.cast<cd>()) + G.D.cast<cd>();
  return Eigen::JacobiSVD<Eigen::MatrixXcd>(H).singularValues()(0);
}

// The largest σ_max on a grid of [0, π] dense near θ = 0 (where slow sampling's peaks sit),
// then zoomed around the best point: a lower bound on the loop's ℓ2 gain.
double sampled_sweep_max(const hinf::StateSpace& G) {
  double best = 0, at = 0;
  for (int i = 0; i <= 6000; ++i) {
    const double theta = 3.14159265358979 * std::pow(10.0, -6.0 + 6.0 * i / 6000.0);  // 3e-6 … π
    const double v = sampled_sigma(G, theta);
    if (v > best) best = v, at = theta;
  }
  for (double h = at * 2e-3; h > at * 1e-9; h /= 10)
    for (int k = -10; k <= 10; ++k) {
      const double v = sampled_sigma(G, std::max(0.0, at + k * h));
      if (v > best) best = v, at = std::max(0.0, at + k * h);
    }
  return best;
}

// Every sampled loop of the shipped continuous controller designs the discretise job certifies
// is at or above a dense frequency sweep of it (and within 1e-6): the certificate of a new kind
// of loop against an independent evaluation, at fast and slow periods, both methods.
TEST(SampledLoop, CertifiedGammaIsAtOrAboveADenseSweepOfTheSampledLoop) {
  const hinf::test::ScratchDir dir("sampled_sweep");
  for (const char* name : {"tests/data/controllers/double-integrator.yaml", "configs/tumbling-hold.yaml"}) {
    const std::string config = std::string(HINF_SOURCE_DIR) + "/" + name;
    const auto problem = hinf::synth::load_problem(config);
    const std::string k = dir / "k.yaml";
    write_text(k, problem->solve().file);
    std::ifstream in(config);
    const hinf::GeneralisedPlant P =
        hinf::synth::parse_controller_config(std::string(std::istreambuf_iterator<char>(in), {}), config).plant;
    for (ControllerSampling m : {ControllerSampling::Tustin, ControllerSampling::ZeroOrderHold})
      for (double T : {0.001, 0.01, 0.1, 0.5}) {
        const hinf::synth::DiscretiseOutcome d = problem->discretise(k, T, m);
        if (!d.holds) continue;  // an unstable sampled loop is refused (TooSlowASample…)
        const auto f = hinf::runtime_yaml::parse_controller_yaml(d.file, "discretised");
        const hinf::StateSpace G = hinf::closed_loop(hinf::synth::sample_generalised_plant(P, T, "--zoh"),
                                                     {f.A_K, f.B_K, f.C_K, f.D_K});
        const double sweep = sampled_sweep_max(G);
        EXPECT_LE(sweep, d.gamma * (1 + 1e-12)) << name << " " << to_string(m) << " T = " << T;
        EXPECT_LE(d.gamma, sweep * (1 + 1e-6)) << name << " " << to_string(m) << " T = " << T;
      }
  }
}

TEST(SampledLoop, VerifyReadsTheDiscretisedFileOnTheSampledPlant) {
  const hinf::test::ScratchDir dir("sampled_verify");
  const std::string k = continuous_design(dir);
  const auto problem = hinf::synth::load_problem(kSampledLoopConfig);
  const hinf::synth::DiscretiseOutcome d = problem->discretise(k, 0.1, ControllerSampling::Tustin);
  ASSERT_TRUE(d.holds) << d.report;
  write_text(dir / "kd.yaml", d.file);
  EXPECT_TRUE(problem->verify(dir / "kd.yaml").holds);
  // the same controller claiming the continuous loop's (lower) γ is not verified on the sampled plant
  std::string lower = d.file;
  const auto at = lower.find("\ngamma: ");
  ASSERT_NE(at, std::string::npos);
  const auto end = lower.find('\n', at + 1);
  lower.replace(at, end - at, "\ngamma: 2.62");
  write_text(dir / "kd-lower.yaml", lower);
  const hinf::synth::VerifyOutcome v = problem->verify(dir / "kd-lower.yaml");
  EXPECT_FALSE(v.holds) << v.report;
  // check compares a synthesis with its continuous-time file, not a discretised one
  EXPECT_THROW(problem->check(dir / "kd.yaml", 1e-6), hinf::Error);
}

TEST(SampledLoop, TooSlowASampleIsNotCertifiedAndSaysWhy) {
  const hinf::test::ScratchDir dir("sampled_slow");
  const std::string k = continuous_design(dir);
  const hinf::synth::DiscretiseOutcome d =
      hinf::synth::load_problem(kSampledLoopConfig)->discretise(k, 2.0, ControllerSampling::ZeroOrderHold);
  EXPECT_FALSE(d.holds);
  EXPECT_FALSE(d.certificate.stable);
  EXPECT_TRUE(d.file.empty());
  EXPECT_NE(d.report.find("NOT certified: the sampled loop is unstable"), std::string::npos) << d.report;
}

// What the job refuses, with the code and the key named.
void expect_refused_naming(const std::function<void()>& f, const std::string& key, const std::string& words) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one naming " << key;
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput) << e.what();
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(SampledLoop, RefusalsNameTheInput) {
  const hinf::test::ScratchDir dir("sampled_refusals");
  const std::string k = continuous_design(dir);
  const auto problem = hinf::synth::load_problem(kSampledLoopConfig);
  for (double T : {0.0, -1.0, double(NAN), double(INFINITY)})
    expect_refused_naming([&] { problem->discretise(k, T, ControllerSampling::Tustin); }, "--tustin",
                   "must be a positive, finite period");
  const hinf::synth::DiscretiseOutcome d = problem->discretise(k, 0.1, ControllerSampling::Tustin);
  write_text(dir / "kd.yaml", d.file);
  expect_refused_naming([&] { problem->discretise(dir / "kd.yaml", 0.1, ControllerSampling::Tustin); }, "--tustin",
                 "already a discrete-time controller");
  // another config (the same plant with a comment added): not the one the controller was designed for
  std::ifstream in(kSampledLoopConfig);
  write_text(dir / "other.yaml", "# another config\n" + std::string(std::istreambuf_iterator<char>(in), {}));
  expect_refused_naming([&] { hinf::synth::load_problem(dir / "other.yaml")->discretise(k, 0.1, ControllerSampling::Tustin); },
                 "config", "was synthesised from a config of sha256");
  const std::string filter = std::string(HINF_SOURCE_DIR) + "/configs/example-matrices.yaml";
  expect_refused_naming([&] { hinf::synth::load_problem(filter)->discretise(k, 0.1, ControllerSampling::ZeroOrderHold); },
                 "config", "is a filter config");
  // the codegen entry: a period needs the config, the config a period, one period at a time
  expect_refused_naming([&] { hinf::synth::discretise_for_codegen(k, "", 0.1, std::nullopt); }, "config", "--config CONFIG");
  expect_refused_naming([&] { hinf::synth::discretise_for_codegen(k, kSampledLoopConfig, std::nullopt, std::nullopt); }, "config",
                 "only with --tustin or --zoh");
  expect_refused_naming([&] { hinf::synth::discretise_for_codegen(k, kSampledLoopConfig, 0.1, 0.1); }, "tustin", "give one");
  EXPECT_FALSE(hinf::synth::discretise_for_codegen(k, "", std::nullopt, std::nullopt).has_value());
}

TEST(SampledLoop, TheFileReaderHoldsTheDiscretisedSection) {
  const std::string head =
      "format: hinf-controller/1\nconfig_sha256: " + std::string(64, 'a') +
      "\ntime: discrete\nsample_time: 0.1\ncontroller: {A_K: [[0.5]], B_K: [[1]], C_K: [[1]], D_K: [[0]]}\n";
  const auto f = hinf::runtime_yaml::parse_controller_yaml(
      head + "discretised: {method: zoh, continuous_gamma: 2, plant_sampling: zoh}\n", "k");
  ASSERT_TRUE(f.discretised.has_value());
  EXPECT_EQ(f.discretised->method, "zoh");
  EXPECT_EQ(*f.discretised->continuous_gamma, 2.0);
  const auto refused = [&](const std::string& text, const std::string& words) {
    try {
      hinf::runtime_yaml::parse_controller_yaml(text, "k");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const hinf::Error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused(head + "discretised: {method: euler}\n", "discretised.method");
  refused(head + "discretised: {method: zoh, plant_sampling: tustin}\n", "discretised.plant_sampling");
  refused(head + "discretised: {method: zoh, continuous_gamma: -1}\n", "discretised.continuous_gamma");
  refused(head + "discretised: {method: zoh, rate: 3}\n", "rate");
  std::string continuous = head;
  continuous.replace(continuous.find("time: discrete\nsample_time: 0.1\n"), 31, "time: continuous\n");
  refused(continuous + "discretised: {method: zoh}\n", "only with time: discrete");
}

}  // namespace
