// Structural checks of the uncertain plant of docs/maths.md (1)–(4):
//   A n×n, B n×p, C m×n, D m×q, L l×n, H n×j, E k×n (H and E both present or both absent),
//   G n×r (optional known input, (120)).
#include <cmath>
#include <string>

#include "hinf/common/number_text.hpp"
#include "hinf/synth/validate_plant.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {
namespace {

// Error(InvalidInput) "NAME<what>", naming the matrix as docs/maths.md (1)–(4) does; a
// reader re-keys it to where the matrix came from (Error::rekeyed).
[[noreturn]] void fail_plant(const std::string& name, const std::string& what) {
  throw Error::invalid_field(name, what);
}

std::string plant_dims(const Eigen::MatrixXd& M) {
  return std::to_string(M.rows()) + "x" + std::to_string(M.cols());
}

void require_nonempty(const Eigen::MatrixXd& M, const std::string& name, const char* what) {
  if (M.rows() == 0 || M.cols() == 0)
    fail_plant(name, ": must not be empty (" + std::string(what) + "), got " + plant_dims(M));
}

void require_rows(const Eigen::MatrixXd& M, const std::string& name, Eigen::Index rows,
                  const char* source) {
  if (M.rows() != rows)
    fail_plant(name, ": expected " + std::to_string(rows) + " rows (" + source + "), got " +
         std::to_string(M.rows()));
}

void require_cols(const Eigen::MatrixXd& M, const std::string& name, Eigen::Index cols,
                  const char* source) {
  if (M.cols() != cols)
    fail_plant(name, ": expected " + std::to_string(cols) + " columns (" + source + "), got " +
         std::to_string(M.cols()));
}

// The synthesis squares the data (γ², EᵀE, the LMI's products): an entry above this
// would overflow there, whatever the units chosen for the signals.
constexpr double kMaxEntryMagnitude = 1e150;

void require_finite(const Eigen::MatrixXd& M, const std::string& name) {
  for (Eigen::Index j = 0; j < M.cols(); ++j)
    for (Eigen::Index i = 0; i < M.rows(); ++i) {
      const std::string entry = ": entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ") = " +
                                number_text(M(i, j));
      if (!std::isfinite(M(i, j))) fail_plant(name, entry + " is not finite");
      if (std::abs(M(i, j)) > kMaxEntryMagnitude)
        fail_plant(name, entry + ": magnitude above 1e150, whose square (γ², EᵀE) overflows; express the "
                           "signals in other units");
    }
}

}  // namespace

void validate_plant(const Plant& plant) {
  const Eigen::MatrixXd& A = plant.A;
  require_nonempty(A, "A", "n >= 1");
  if (A.rows() != A.cols())
    fail_plant("A", ": must be square (n x n), got " + plant_dims(A));
  const Eigen::Index n = A.rows();

  require_rows(plant.B, "B", n, "n from A");
  require_nonempty(plant.B, "B", "p >= 1 noise inputs");
  require_cols(plant.C, "C", n, "n from A");
  require_nonempty(plant.C, "C", "m >= 1 measurements");
  require_rows(plant.D, "D", plant.C.rows(), "m from C");
  require_nonempty(plant.D, "D", "q >= 1 noise inputs");
  require_cols(plant.L, "L", n, "n from A");
  require_nonempty(plant.L, "L", "l >= 1 estimated signals");

  const bool has_H = plant.H.size() > 0;
  const bool has_E = plant.E.size() > 0;
  if (has_H && !has_E)
    fail_plant("H", " is given (" + plant_dims(plant.H) + ") but E is empty: "
         "Delta A = H F E needs both");
  if (has_E && !has_H)
    fail_plant("E", " is given (" + plant_dims(plant.E) + ") but H is empty: "
         "Delta A = H F E needs both");
  if (has_H) {
    require_rows(plant.H, "H", n, "n from A");
    require_cols(plant.E, "E", n, "n from A");
  }

  if (plant.G.size() > 0) require_rows(plant.G, "G", n, "n from A");
  if (!plant.F_blocks.empty()) {
    long total = 0;
    for (int b : plant.F_blocks) {
      if (b <= 0) fail_plant("F_blocks", ": a block size " + std::to_string(b) + " is not positive");
      total += b;
    }
    if (!has_H || total != plant.H.cols() || total != plant.E.rows())
      fail_plant("F_blocks", ": the block sizes add up to " + std::to_string(total) + ", but F is " +
                           std::to_string(plant.E.rows()) + "x" + std::to_string(plant.H.cols()) +
                           " (rows of E x columns of H); the blocks are square and cover F");
  }

  require_finite(A, "A");
  require_finite(plant.B, "B");
  require_finite(plant.C, "C");
  require_finite(plant.D, "D");
  require_finite(plant.L, "L");
  require_finite(plant.H, "H");
  require_finite(plant.E, "E");
  require_finite(plant.G, "G");
}

}  // namespace hinf::synth
