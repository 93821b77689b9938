// verify_controller, compare_controller_with_golden (controller_regression.hpp).
#include "hinf/synth/controller_regression.hpp"

#include <algorithm>
#include <cmath>

#include "hinf/certify/balance.hpp"
#include "hinf/certify/controller_certificate.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {
namespace {

// A golden controller within this relative γ still counts as optimal (as for filters).
constexpr double kControllerEquallyOptimalTolerance = 1e-6;
// Relative accuracy of the controllers' H∞ norms.
constexpr double kGoldenNormTolerance = 1e-9;

hinf::StateSpace as_system(const hinf::Controller& K) { return {K.A_K, K.B_K, K.C_K, K.D_K}; }

bool stable(const hinf::Controller& K, bool discrete) {
  if (K.A_K.rows() == 0) return true;
  const Eigen::VectorXcd l = certify::balanced_eigenvalues(K.A_K);
  return discrete ? l.cwiseAbs().maxCoeff() < 1 : l.real().maxCoeff() < 0;
}

double hinf_norm(const hinf::StateSpace& s, bool discrete) {
  return (discrete ? certify::discrete_hinf_norm(s, kGoldenNormTolerance) : certify::continuous_hinf_norm(s, kGoldenNormTolerance)).norm;
}

// ‖K_a − K_b‖∞ / ‖K_a‖∞, both controllers stable.
double relative_difference(const hinf::Controller& a, const hinf::Controller& b, bool discrete) {
  const Eigen::Index na = a.A_K.rows(), nb = b.A_K.rows();
  hinf::StateSpace d;
  d.A = Eigen::MatrixXd::Zero(na + nb, na + nb);
  d.A.topLeftCorner(na, na) = a.A_K;
  d.A.bottomRightCorner(nb, nb) = b.A_K;
  d.B.resize(na + nb, a.B_K.cols());
  d.B << a.B_K, b.B_K;
  d.C.resize(a.C_K.rows(), na + nb);
  d.C << a.C_K, -b.C_K;
  d.D = a.D_K - b.D_K;
  const double reference = hinf_norm(as_system(a), discrete);
  const double difference = hinf_norm(d, discrete);
  return reference > 0 ? difference / reference : (difference > 0 ? INFINITY : 0.0);
}

}  // namespace

ControllerVerification verify_controller(const hinf::GeneralisedPlant& P, const certify::ControllerChecks& checks,
                                         const hinf::Controller& K, double claimed_gamma) {
  certify::require_controller_fits(P, K);
  ControllerVerification v;
  v.certificate = certify::certify_controller(P, K, claimed_gamma, checks);
  v.holds = v.certificate.passed;
  return v;
}

ControllerGoldenComparison compare_controller_with_golden(const ControllerConfig& config, const hinf::Controller& golden,
                                                          double golden_gamma, const ControllerSynthesisResult& now,
                                                          double rtol) {
  certify::require_controller_fits(config.plant, golden);
  const bool discrete = config.plant.time == hinf::TimeDomain::Discrete;
  ControllerGoldenComparison c;
  // a golden γ of 0 (T_zw ≡ 0): the same only when the new one is 0 too
  c.gamma_relative_change = now.gamma == golden_gamma ? 0.0 : std::abs(now.gamma - golden_gamma) / std::abs(golden_gamma);
  c.same_gamma = c.gamma_relative_change <= rtol;
  if (stable(golden, discrete) && stable(now.controller, discrete))
    c.controller_difference = relative_difference(golden, now.controller, discrete);
  c.same_controller = c.controller_difference && *c.controller_difference <= rtol;
  if (!c.same_controller) {  // not unique at the optimum: is the golden one still certified?
    const double tol = std::min(rtol, kControllerEquallyOptimalTolerance);
    c.golden_recertified = certify::certify_controller(config.plant, golden, golden_gamma * (1 + tol), config.design.checks());
    c.same_controller = c.golden_recertified->passed;
  }
  return c;
}

}  // namespace hinf::synth
