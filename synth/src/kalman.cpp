// The Kalman one-step predictor (or, with filter.estimate: filtered, the Kalman filter's
// x̂(k|k), (143) at γ = ∞) as a gains file (docs/maths.md (133)): the reference the H∞
// filter is compared with — its RMS error under white noise is the least any predictor
// achieves, its worst-case gain is what the H∞ design improves on.
#include <cmath>
#include <limits>

#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/riccati_filter.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/models/discretise.hpp"
#include "hinf/synth/synthesis.hpp"
#include "hinf/synth/validate_plant.hpp"
#include "pipeline.hpp"

namespace hinf::synth {
namespace {
// The γ written is the achieved bound rounded up by this (it must pass the certificate).
constexpr double kClaimMargin = 1e-7;
// Q, R: asymmetry and negative eigenvalues up to this fraction of the largest entry are rounding.
constexpr double kSymmetryTolerance = 1e-12;

// A symmetric matrix's definiteness: "" if it holds, else what is wrong.
std::string definiteness_defect(const Eigen::MatrixXd& M, bool strict) {
  const double scale = M.cwiseAbs().maxCoeff();
  if (!((M - M.transpose()).cwiseAbs().maxCoeff() <= kSymmetryTolerance * scale)) return ": not symmetric";
  const double lmin = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M, Eigen::EigenvaluesOnly).eigenvalues()(0);
  if (strict && !(lmin > 0)) return ": not positive definite (smallest eigenvalue " + significant_text(lmin, 10) + ")";
  if (!strict && lmin < -kSymmetryTolerance * scale)
    return ": not positive semidefinite (smallest eigenvalue " + significant_text(lmin, 10) + ")";
  return "";
}

}  // namespace

void validate_kalman_noise(const KalmanNoise& noise, const Plant& plant) {
  const auto check = [](const Eigen::MatrixXd& M, const char* name, int size, bool strict) {
    if (M.size() == 0) return;
    if (M.rows() != size || M.cols() != size)
      throw Error::invalid_field(name, ": expected " + std::to_string(size) + "x" + std::to_string(size) + ", got " +
                                           std::to_string(M.rows()) + "x" + std::to_string(M.cols()));
    if (!M.allFinite()) throw Error::invalid_field(name, ": an entry is not finite");
    const std::string defect = definiteness_defect(M, strict);
    if (!defect.empty()) throw Error::invalid_field(name, defect);
  };
  check(noise.Q, "Q", plant.n(), false);
  check(noise.R, "R", plant.m(), true);
}

SynthesisResult kalman_predictor(const Plant& plant, const Settings& settings, const KalmanNoise& noise) {
  validate_plant(plant);
  settings.validate();
  validate_kalman_noise(noise, plant);
  Plant design = plant;  // the plant whose B Bᵀ, D Dᵀ are the covariances (docs/maths.md (133))
  if (noise.Q.size() > 0) design.B = models::covariance_factor(noise.Q);
  if (noise.R.size() > 0) design.D = models::covariance_factor(noise.R);
  const certify::HinfPredictorLevel kf =
      certify::hinf_predictor_at_level(design, std::numeric_limits<double>::infinity(), settings.estimate);
  if (!kf.feasible)
    throw Error(ErrorCode::Infeasible,
                "no stationary Kalman predictor: " + kf.reason +
                    " (the DARE needs (A, C) detectable and no mode on the unit circle unreached by the noise B)");
  SynthesisResult r;
  r.filter = kf.filter;
  const bool filtered = settings.estimate == Estimate::Filtered;
  r.solver.method = std::string(filtered ? "Kalman filter, estimate x_hat(k|k) (docs/maths.md (143)), "
                                         : "Kalman one-step predictor: ") +
                    "stabilising DARE solution by ordered QZ (docs/maths.md (56)-(59) at gamma = infinity, " +
                    std::string(noise.Q.size() > 0 ? "Q given" : "Q = B B^T") + ", " +
                    (noise.R.size() > 0 ? "R given" : "R = D D^T") + ")";
  const double nominal = certify::discrete_hinf_norm(certify::error_system(plant, r.filter), 1e-10).norm;
  double claim = nominal * (1 + kClaimMargin);
  if (plant.uncertain()) claim = std::max(claim, robust_bound(plant, r.filter, settings) * (1 + kClaimMargin));
  r.certificate = certify_filter(plant, r.filter, claim, settings);
  if (!r.certificate.passed)
    throw Error(ErrorCode::NumericalFailure, std::string(filtered ? "the Kalman filter's" : "the Kalman predictor's") +
                                                 " certificate failed at gamma = " + significant_text(claim, 10) + ":" +
                                                 failed_checks(r.certificate, claim) + " no gains written");
  r.gamma = claim;
  r.gamma_squared = claim * claim;
  r.bound = bound_statement(FilterForm::Observer, plant.uncertain(), settings.estimate);
  return r;
}

}  // namespace hinf::synth
