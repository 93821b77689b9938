// F's admissible set when F is block-diagonal (docs/maths.md §23): the one projection
// behind check 2's samples (stability.cpp) and the worst-case search (worst_case.cpp).
#pragma once
#include <Eigen/Dense>

#include "hinf/models/plant.hpp"

namespace hinf::certify::detail {

// What happens to the norm of each block (the whole F when F is one block).
enum class BlockNorm {
  Kept,       // as given
  One,        // scaled to spectral norm 1 (a zero block stays zero); F one block: unchanged
  AtMostOne,  // scaled down to spectral norm 1 when above it
};

// F with everything outside F's diagonal blocks zeroed, each block's norm as `norm` says.
inline Eigen::MatrixXd onto_blocks(const Plant& plant, const Eigen::MatrixXd& F, BlockNorm norm) {
  const auto scaled = [norm](Eigen::MatrixXd M) {
    if (norm == BlockNorm::Kept) return M;
    const double s = Eigen::JacobiSVD<Eigen::MatrixXd>(M).singularValues()(0);
    if ((norm == BlockNorm::One && s > 0) || (norm == BlockNorm::AtMostOne && s > 1)) M /= s;
    return M;
  };
  if (!plant.structured()) return norm == BlockNorm::AtMostOne ? scaled(F) : F;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(F.rows(), F.cols());
  for (const auto& [at, size] : plant.F_block_ranges()) out.block(at, at, size, size) = scaled(F.block(at, at, size, size));
  return out;
}

}  // namespace hinf::certify::detail
