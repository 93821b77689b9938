// The observer-form pipeline (docs/maths.md §18): pre-flight (detectability, (126)), the
// LMI (124) (or (142) for the filtered estimate) by the barrier method, the optional γ
// back-off, recovery (125), (144) and the certificate of §7 on the error dynamics (122)–(123), (141).
#include <cmath>
#include <complex>
#include <optional>
#include <sstream>

#include "hinf/certify/pbh.hpp"
#include "hinf/certify/stability.hpp"
#include "observer_lmi.hpp"
#include "pipeline.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

std::string complex_text(std::complex<double> z) {
  if (z.imag() == 0) return fmt(z.real());
  return fmt(z.real()) + (z.imag() >= 0 ? " + " : " - ") + fmt(std::abs(z.imag())) + "i";
}

std::string vector_text(const Eigen::VectorXcd& v) {
  std::string s = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + complex_text(v(i));
  return s + "]";
}

// The direction v (‖v‖ = 1, largest entry real and positive) of an undetectable mode λ
// (|λ| ≥ 1, (A − λI)v ≈ 0, Cv ≈ 0), if any: the PBH test of (126) at each eigenvalue of the
// scaled plant; v and its residuals are reported in the user's state coordinates
// (x = diag(state_scale) x̃, docs/maths.md §4.4). The verdict must hold in the user's
// coordinates too: a plant sampled at 1e-10 s has, scaled, a subdiagonal below rounding that
// deflates a mode at |λ| = 1 − 1e-11 to λ = 1 exactly, and was called undetectable.
void require_detectable(const Plant& plant, const VectorXd& state_scale) {
  const std::optional<certify::UnseenMode> mode = certify::unseen_unstable_mode(plant.A, plant.C, /*discrete=*/true);
  if (!mode) return;
  const MatrixXd A_user = state_scale.asDiagonal() * plant.A * state_scale.cwiseInverse().asDiagonal();
  const MatrixXd C_user = plant.C * state_scale.cwiseInverse().asDiagonal();
  if (!certify::unseen_unstable_mode(A_user, C_user, /*discrete=*/true)) return;
  const std::complex<double> lambda = mode->lambda;
  Eigen::VectorXcd v = state_scale.cast<std::complex<double>>().asDiagonal() * mode->direction;
  v.normalize();
  Eigen::Index big = 0;
  v.cwiseAbs().maxCoeff(&big);
  v *= std::abs(v(big)) / v(big);
  const Eigen::VectorXcd v_scaled = state_scale.cwiseInverse().cast<std::complex<double>>().asDiagonal() * v;
  const Eigen::VectorXcd Av = (plant.A.cast<std::complex<double>>() * v_scaled - lambda * v_scaled);
  const Eigen::VectorXcd Cv = plant.C.cast<std::complex<double>>() * v_scaled;
  throw Error(ErrorCode::Infeasible,
              "infeasible: the mode λ = " + complex_text(lambda) + " of A (|λ| = " + fmt(std::abs(lambda)) +
                  " ≥ 1) is not detectable from y: for the direction v = " + vector_text(v) +
                  " (in the plant's state coordinates), residuals ‖(A − λI)v‖ = " + fmt(Av.norm()) +
                  " and ‖C v‖ = " + fmt(Cv.norm()) + " in the scaled units of docs/maths.md §4.4" +
                  ", so e = x − x̂ keeps this mode for every gain K and no filter makes the error stable "
                  "(docs/maths.md (126)); measure this mode, or leave it out of the model");
}

void preflight_observer(const Plant& plant, const VectorXd& state_scale, Estimate estimate) {
  if (plant.L.isZero(0.0))
    throw Error(ErrorCode::Infeasible,
                "ill-posed: the estimated-output matrix L is zero, so there is no output to estimate and γ* = 0; nothing to synthesise");
  if (estimate == Estimate::Filtered) {  // M = L⁺ N must give L M = N (docs/maths.md (144))
    const Eigen::Index rank = Eigen::CompleteOrthogonalDecomposition<MatrixXd>(plant.L).rank();
    if (rank < plant.l())
      throw Error(ErrorCode::InvalidInput,
                  "filter.estimate: filtered needs L with independent rows (rank " + std::to_string(rank) + " < " +
                      std::to_string(plant.l()) + " rows of system.L), so that the gain M of x̂(k|k) exists "
                      "(docs/maths.md (144)); remove the dependent rows of L");
  }
  require_detectable(plant, state_scale);
  if (plant.B.isZero(0.0) && certify::spectral_radius(plant.A) < 1.0)
    throw Error(ErrorCode::Infeasible,
                "ill-posed: the process-noise matrix B is zero and A is Schur stable, so K = 0 makes the error decay "
                "with no input at all: γ* = 0 (docs/maths.md §2.4); nothing to synthesise");
}

}  // namespace

SynthesisResult synthesize_observer(const Plant& plant, const PlantScaling& sc, const Settings& settings,
                                    const IterationObserver& observer) {
  preflight_observer(plant, sc.state, settings.estimate);
  const ObserverLmi O = build_observer_lmi(plant, settings.estimate);
  const std::vector<lmi::SparseEntry> basis_error = observer_basis_error(O, plant);
  const sdp::Solution sol =
      solve_min_gamma(O.lmi, O.g, basis_error, settings, observer, "observer-form LMI",
                      plant.structured() ? structured_infeasible_hint()
                                         : " (no gain K makes A + H F E − K C quadratically stable for every "
                                           "admissible F: reduce the uncertainty H, E)");
  SynthesisResult res;
  res.solver = solver_info(sol, O.lmi, sc, settings);
  record_bracket(O.lmi, O.g, basis_error, sol, settings, sc.gamma_factor(), res.solver);

  const auto backoff = solve_gamma_backoff<ObserverLmi>(
      sol, [&](double g2) { return build_observer_lmi_backoff(plant, g2, settings.estimate); }, settings, observer,
      res.solver);
  certify::ObserverPoint pt = backoff ? observer_point(backoff->problem, plant, backoff->solution.x, backoff->gamma_squared)
                                      : observer_point(O, plant, sol.x, sol.objective);
  res.filter = recover_observer(pt, plant);
  if (res.filter.filtered()) pt.N = res.filter.D_F;  // check 1 at the N = L M written, not the solver's N
  certify_at_point(plant, certify::observer_lmi_matrix(plant, pt), pt.g, settings, pt.lambda, res);
  const VectorXd eig_P = Eigen::SelfAdjointEigenSolver<MatrixXd>(pt.P, Eigen::EigenvaluesOnly).eigenvalues();
  res.certificate.cond_P = eig_P(eig_P.size() - 1) / eig_P(0);
  return res;
}

}  // namespace hinf::synth
