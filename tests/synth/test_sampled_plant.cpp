// Continuous-time plants (docs/maths.md §19): the three samplings and Van Loan's covariance
// against closed forms, and a continuous-time config synthesising the same γ as the plant
// sampled by hand; bad sampling keys named.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/models/discretise.hpp"
#include "hinf/synth/config.hpp"
#include "hinf/synth/synthesis.hpp"

namespace {

using Eigen::MatrixXd;
using hinf::models::Discretisation;

MatrixXd m2(double a, double b, double c, double d) {
  MatrixXd M(2, 2);
  M << a, b, c, d;
  return M;
}

TEST(Sampling, DoubleIntegratorClosedForms) {
  const double T = 0.1;
  const MatrixXd A = m2(0, 1, 0, 0), B = (MatrixXd(2, 1) << 0, 1).finished();
  const MatrixXd Ad = m2(1, T, 0, 1), Bd = (MatrixXd(2, 1) << T * T / 2, T).finished();
  for (Discretisation d : {Discretisation::ZeroOrderHold, Discretisation::Tustin}) {
    const auto s = hinf::models::discretise(A, T, d);  // A² = 0: both are exact here
    EXPECT_LT((s.A - Ad).norm(), 1e-15) << to_string(d);
    EXPECT_LT((s.Gamma * B - Bd).norm(), 1e-15) << to_string(d);
  }
  const auto e = hinf::models::discretise(A, T, Discretisation::Euler);
  EXPECT_EQ(e.A, Ad);
  EXPECT_EQ(e.Gamma * B, (MatrixXd(2, 1) << 0, T).finished());
}

TEST(Sampling, OscillatorZohAndScalarTustinAndVanLoan) {
  const double w = 3.0, T = 0.2, c = std::cos(w * T), s = std::sin(w * T);
  const auto z = hinf::models::discretise(m2(0, 1, -w * w, 0), T, Discretisation::ZeroOrderHold);
  EXPECT_LT((z.A - m2(c, s / w, -w * s, c)).norm(), 1e-14);
  EXPECT_LT((z.Gamma - m2(s / w, (1 - c) / (w * w), c - 1, s / w)).norm(), 1e-14);
  const double a = 2.0, b = 0.7;
  const MatrixXd Ac = MatrixXd::Constant(1, 1, -a);
  const auto t = hinf::models::discretise(Ac, T, Discretisation::Tustin);
  EXPECT_NEAR(t.A(0, 0), (1 - a * T / 2) / (1 + a * T / 2), 1e-15);
  EXPECT_NEAR(t.Gamma(0, 0), T / (1 + a * T / 2), 1e-15);
  const auto h = hinf::models::discretise(Ac, T, Discretisation::ZeroOrderHold);
  EXPECT_NEAR(h.A(0, 0), std::exp(-a * T), 1e-15);
  EXPECT_NEAR(h.Gamma(0, 0), (1 - std::exp(-a * T)) / a, 1e-15);
  const MatrixXd Q = hinf::models::sampled_white_noise_covariance(Ac, MatrixXd::Constant(1, 1, b), T);
  EXPECT_NEAR(Q(0, 0) / (b * b * (1 - std::exp(-2 * a * T)) / (2 * a)), 1.0, 1e-13);
}

const char* const kDiscrete = R"(system:
  A: [[1, 0.1], [0, 1]]
  B: [[0.005], [0.1]]
  C: [[1, 0]]
  D: [[0.5]]
  L: {diag: [1, 1]}
)";

std::string continuous(const std::string& method) {
  return "system:\n  A: [[0, 1], [0, 0]]\n  B: [[0], [1]]\n  C: [[1, 0]]\n  D: [[0.5]]\n  L: {diag: [1, 1]}\n"
         "  sample_time: 0.1\n  discretisation: " + method + "\n";
}

TEST(Sampling, ContinuousConfigGivesTheGammaOfTheHandSampledPlant) {
  const double g_hand = hinf::synth::synthesize(hinf::synth::parse_config(kDiscrete, "d.yaml").plant, {}).gamma;
  for (const char* method : {"zoh", "tustin"}) {
    const hinf::synth::SynthConfig c = hinf::synth::parse_config(continuous(method), "c.yaml");
    ASSERT_TRUE(c.sample_time());
    EXPECT_EQ(*c.sample_time(), 0.1);
    const double g = hinf::synth::synthesize(c.plant, c.settings).gamma;
    EXPECT_NEAR(g / g_hand, 1.0, 1e-8) << method;
  }
}

TEST(Sampling, WhiteProcessNoiseIsTheVanLoanFactor) {
  const hinf::synth::SynthConfig c =
      hinf::synth::parse_config(continuous("zoh") + "  process_noise: white\n", "c.yaml");
  const double T = 0.1;  // ∫₀ᵀ [s; 1][s, 1] ds for the double integrator
  const MatrixXd Q = (MatrixXd(2, 2) << T * T * T / 3, T * T / 2, T * T / 2, T).finished();
  EXPECT_LT((c.plant.B * c.plant.B.transpose() - Q).norm(), 1e-15);
}

std::string error_of(const std::string& text) {
  try {
    hinf::synth::parse_config(text, "c.yaml");
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

TEST(Sampling, BadKeysAreNamed) {
  EXPECT_HAS(error_of(std::string(kDiscrete) + "  discretisation: zoh\n"), "system.discretisation");
  EXPECT_HAS(error_of(std::string(kDiscrete) + "  process_noise: white\n"), "system.process_noise");
  EXPECT_HAS(error_of(continuous("zho")), "system.discretisation");
  std::string negative = continuous("zoh");
  negative.replace(negative.find("0.1\n"), 4, "-0.1\n");
  EXPECT_HAS(error_of(negative), "system.sample_time");
  std::string huge = continuous("zoh");
  huge.replace(huge.find("A: [[0, 1], [0, 0]]"), 19, "A: [[50, 1], [0, 0]]");
  huge.replace(huge.find("0.1\n"), 4, "1e300\n");
  EXPECT_HAS(error_of(huge), "system.sample_time");
}

}  // namespace
