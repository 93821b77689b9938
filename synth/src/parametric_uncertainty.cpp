// Named uncertain parameters as H F E (docs/maths.md §22).
#include "hinf/synth/parametric_uncertainty.hpp"

#include <algorithm>
#include <limits>

namespace hinf::synth {
namespace {

// A column of Aᵢ is a combination of the earlier kept ones when its residual after the
// least-squares fit is at most this fraction of its norm (rounding level: the H X
// written then equals Aᵢ to that accuracy).
constexpr double kDependentColumn = 16 * std::numeric_limits<double>::epsilon();

// Aᵢ = Aᵢ[:, P] X with P the columns of Aᵢ that are not combinations of earlier ones,
// left to right (docs/maths.md (138)); X(k, P[k]) = 1.
void column_skeleton(const Eigen::MatrixXd& Ai, Eigen::MatrixXd& H, Eigen::MatrixXd& X) {
  std::vector<Eigen::Index> kept;
  std::vector<std::pair<Eigen::Index, Eigen::VectorXd>> combined;
  for (Eigen::Index c = 0; c < Ai.cols(); ++c) {
    if ((Ai.col(c).array() == 0).all()) continue;
    if (!kept.empty()) {
      Eigen::MatrixXd Hk(Ai.rows(), static_cast<Eigen::Index>(kept.size()));
      for (std::size_t k = 0; k < kept.size(); ++k) Hk.col(static_cast<Eigen::Index>(k)) = Ai.col(kept[k]);
      const Eigen::VectorXd coef = Hk.colPivHouseholderQr().solve(Ai.col(c));
      if ((Hk * coef - Ai.col(c)).norm() <= kDependentColumn * Ai.col(c).norm()) {
        combined.emplace_back(c, coef);
        continue;
      }
    }
    kept.push_back(c);
  }
  const auto k = static_cast<Eigen::Index>(kept.size());
  H.resize(Ai.rows(), k);
  X = Eigen::MatrixXd::Zero(k, Ai.cols());
  for (Eigen::Index i = 0; i < k; ++i) {
    H.col(i) = Ai.col(kept[static_cast<std::size_t>(i)]);
    X(i, kept[static_cast<std::size_t>(i)]) = 1;
  }
  for (const auto& [c, coef] : combined) X.col(c).head(coef.size()) = coef;
}

}  // namespace

double UncertainParameter::radius() const { return std::max(high - nominal, nominal - low); }

UncertaintyFactors uncertainty_from_parameters(const std::vector<Eigen::MatrixXd>& coefficients,
                                               const std::vector<UncertainParameter>& parameters, Eigen::Index n) {
  const Eigen::Index cols = coefficients.empty() ? n : coefficients.front().cols();
  std::vector<Eigen::MatrixXd> Hs, Es;
  Eigen::Index j = 0;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    Eigen::MatrixXd Hi, Xi;
    column_skeleton(coefficients[i], Hi, Xi);
    Hs.push_back(Hi);
    Es.push_back(parameters[i].radius() * Xi);  // (138): E rows rᵢ X
    j += Hi.cols();
  }
  UncertaintyFactors f{Eigen::MatrixXd::Zero(n, j), Eigen::MatrixXd::Zero(j, cols), {}, {}};
  Eigen::Index at = 0;
  for (std::size_t i = 0; i < Hs.size(); ++i) {
    f.H.middleCols(at, Hs[i].cols()) = Hs[i];
    f.E.middleRows(at, Es[i].rows()) = Es[i];
    at += Hs[i].cols();
    if (Hs[i].cols() == 0) continue;
    f.blocks.push_back(static_cast<int>(Hs[i].cols()));
    f.parameter_blocks.push_back({parameters[i], static_cast<int>(Hs[i].cols())});
  }
  if (f.blocks.size() < 2) f.blocks.clear();  // one block: F full
  return f;
}

}  // namespace hinf::synth
