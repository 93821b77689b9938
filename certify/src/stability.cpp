// Spectral radius and sampled robust stability; see stability.hpp.
#include "hinf/certify/stability.hpp"

#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

#include "admissible_f.hpp"
#include "gaussian_source.hpp"
#include "hinf/certify/balance.hpp"
#include "hinf/certify/error_system.hpp"
#include "hinf/common/error.hpp"

namespace hinf::certify {
namespace {

void add_sample(const Plant& plant, const Filter& filter, const Eigen::MatrixXd& F,
                StabilitySample& out) {
  const double rho = spectral_radius(error_system(plant, filter, F).A);
  if (out.samples == 0 || rho > out.max_spectral_radius) {
    out.max_spectral_radius = rho;
    out.worst_F = F.size() > 0 ? F : Eigen::MatrixXd::Zero(plant.j(), plant.k());
  }
  ++out.samples;
}

}  // namespace

std::complex<double> dominant_eigenvalue(const Eigen::MatrixXd& M) {
  if (M.rows() != M.cols())
    throw Error(ErrorCode::InvalidInput, "spectral_radius: matrix is " + std::to_string(M.rows()) +
                                             "×" + std::to_string(M.cols()) + ", not square");
  if (!M.allFinite()) throw Error(ErrorCode::InvalidInput, "spectral_radius: non-finite entry");
  if (M.size() == 0) return 0.0;
  const Eigen::VectorXcd ev = balanced_eigenvalues(M);  // balanced: docs/maths.md §4.4
  Eigen::Index worst = 0;
  for (Eigen::Index i = 1; i < ev.size(); ++i)
    if (std::abs(ev(i)) > std::abs(ev(worst))) worst = i;
  return ev(worst);
}

double spectral_radius(const Eigen::MatrixXd& M) { return std::abs(dominant_eigenvalue(M)); }

std::vector<Eigen::MatrixXd> admissible_samples(const Plant& plant, int random_samples, unsigned seed) {
  if (random_samples < 0)
    throw Error(ErrorCode::InvalidInput, "sampled_robust_stability: random_samples < 0");
  std::vector<Eigen::MatrixXd> Fs{Eigen::MatrixXd()};  // nominal, F = 0
  if (!plant.uncertain()) return Fs;
  const Eigen::Index j = plant.H.cols(), k = plant.E.rows();
  const Eigen::MatrixXd I_jk = Eigen::MatrixXd::Identity(j, k);
  Fs.push_back(I_jk);
  Fs.push_back(-I_jk);
  for (Eigen::Index a = 0; a < j; ++a) {
    for (Eigen::Index b = 0; b < k; ++b) {
      Eigen::MatrixXd F = Eigen::MatrixXd::Zero(j, k);
      F(a, b) = 1.0;
      if (detail::onto_blocks(plant, F, detail::BlockNorm::Kept)(a, b) == 0) continue;  // outside F's blocks: not admissible
      Fs.push_back(F);
      Fs.push_back(-F);
    }
  }
  detail::GaussianSource gauss(seed);
  for (int s = 0; s < random_samples; ++s) {
    Eigen::MatrixXd G(j, k);
    for (Eigen::Index c = 0; c < k; ++c)
      for (Eigen::Index r = 0; r < j; ++r) G(r, c) = gauss.next();
    if (plant.structured()) {
      Fs.push_back(detail::onto_blocks(plant, G, detail::BlockNorm::One));  // each ‖F_b‖₂ = 1
      continue;
    }
    const double norm = Eigen::JacobiSVD<Eigen::MatrixXd>(G).singularValues()(0);
    if (norm > 0) Fs.push_back(G / norm);  // ‖F‖₂ = 1
  }
  return Fs;
}

StabilitySample sampled_robust_stability(const Plant& plant, const Filter& filter,
                                         int random_samples, unsigned seed) {
  StabilitySample out;
  for (const Eigen::MatrixXd& F : admissible_samples(plant, random_samples, seed)) add_sample(plant, filter, F, out);
  return out;
}

StabilitySample sampled_robust_stability(const Plant& plant, const Filter& filter,
                                         const std::vector<Eigen::MatrixXd>& Fs) {
  StabilitySample out;
  for (std::size_t i = 0; i < Fs.size(); ++i) {
    const Eigen::MatrixXd& F = Fs[i];
    if (F.size() > 0) {
      if (F.rows() != plant.H.cols() || F.cols() != plant.E.rows())
        throw Error(ErrorCode::InvalidInput,
                    "sampled_robust_stability: F[" + std::to_string(i) + "] is " +
                        std::to_string(F.rows()) + "×" + std::to_string(F.cols()) + ", expected " +
                        std::to_string(plant.H.cols()) + "×" + std::to_string(plant.E.rows()));
      if (detail::onto_blocks(plant, F, detail::BlockNorm::Kept) != F)
        throw Error(ErrorCode::InvalidInput, "sampled_robust_stability: F[" + std::to_string(i) +
                                                 "] is not block-diagonal as F's blocks are (not admissible)");
      const double norm = Eigen::JacobiSVD<Eigen::MatrixXd>(F).singularValues()(0);
      if (!(norm <= 1.0 + 1e-12)) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "sampled_robust_stability: F[" << i << "] is not admissible, ‖F‖₂ = " << norm << " > 1";
        throw Error(ErrorCode::InvalidInput, msg.str());
      }
    }
    add_sample(plant, filter, F, out);
  }
  return out;
}

}  // namespace hinf::certify
