// Spectral radius and sampled robust stability; see stability.hpp.
#include "hinf/certify/stability.hpp"

#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

#include "hinf/certify/balance.hpp"
#include "hinf/certify/error_system.hpp"
#include "hinf/common/error.hpp"

namespace hinf::certify {
namespace {

// Standard normal deviates by the Box–Muller transform from raw mt19937_64 output
// (std::normal_distribution is implementation-defined; this is not).
class GaussianSource {
 public:
  explicit GaussianSource(unsigned seed) : engine_(seed) {}
  double next() {
    if (has_spare_) { has_spare_ = false; return spare_; }
    // 53-bit uniforms in (0, 1].
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double t = 2.0 * 3.14159265358979323846 * u2;
    spare_ = r * std::sin(t);
    has_spare_ = true;
    return r * std::cos(t);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

void add_sample(const Plant& plant, const Filter& filter, const Eigen::MatrixXd& F,
                StabilitySample& out) {
  const double rho = spectral_radius(error_system(plant, filter, F).A);
  if (out.samples == 0 || rho > out.max_spectral_radius) {
    out.max_spectral_radius = rho;
    out.worst_F = F.size() > 0 ? F : Eigen::MatrixXd::Zero(plant.j(), plant.k());
  }
  ++out.samples;
}

// F's admissible set when F is block-diagonal (docs/maths.md §23): F outside the blocks is
// zeroed, and with `normalise` each nonzero block is scaled to ‖F_b‖₂ = 1.
Eigen::MatrixXd on_blocks(const Plant& plant, const Eigen::MatrixXd& F, bool normalise) {
  if (!plant.structured()) return F;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(F.rows(), F.cols());
  for (const auto& [at, size] : plant.F_block_ranges()) {
    Eigen::MatrixXd block = F.block(at, at, size, size);
    const double norm = Eigen::JacobiSVD<Eigen::MatrixXd>(block).singularValues()(0);
    if (normalise && norm > 0) block /= norm;
    out.block(at, at, size, size) = block;
  }
  return out;
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

StabilitySample sampled_robust_stability(const Plant& plant, const Filter& filter,
                                         int random_samples, unsigned seed) {
  if (random_samples < 0)
    throw Error(ErrorCode::InvalidInput, "sampled_robust_stability: random_samples < 0");
  StabilitySample out;
  const Eigen::Index j = plant.H.cols(), k = plant.E.rows();
  add_sample(plant, filter, Eigen::MatrixXd(), out);  // nominal, F = 0
  if (!plant.uncertain()) return out;
  const Eigen::MatrixXd I_jk = Eigen::MatrixXd::Identity(j, k);
  add_sample(plant, filter, I_jk, out);
  add_sample(plant, filter, -I_jk, out);
  for (Eigen::Index a = 0; a < j; ++a) {
    for (Eigen::Index b = 0; b < k; ++b) {
      Eigen::MatrixXd F = Eigen::MatrixXd::Zero(j, k);
      F(a, b) = 1.0;
      if (on_blocks(plant, F, false)(a, b) == 0) continue;  // outside F's blocks: not admissible
      add_sample(plant, filter, F, out);
      add_sample(plant, filter, -F, out);
    }
  }
  GaussianSource gauss(seed);
  for (int s = 0; s < random_samples; ++s) {
    Eigen::MatrixXd G(j, k);
    for (Eigen::Index c = 0; c < k; ++c)
      for (Eigen::Index r = 0; r < j; ++r) G(r, c) = gauss.next();
    if (plant.structured()) {
      add_sample(plant, filter, on_blocks(plant, G, true), out);  // each ‖F_b‖₂ = 1
      continue;
    }
    const double norm = Eigen::JacobiSVD<Eigen::MatrixXd>(G).singularValues()(0);
    if (norm > 0) add_sample(plant, filter, G / norm, out);  // ‖F‖₂ = 1
  }
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
      if (on_blocks(plant, F, false) != F)
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
