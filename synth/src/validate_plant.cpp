// Structural checks of the uncertain plant of docs/maths.md (1)–(4):
//   A n×n, B n×p, C m×n, D m×q, L l×n, H n×j, E k×n (H and E both present or both absent).
#include <cmath>
#include <string>

#include "hinf/common/number_text.hpp"
#include "hinf/synth/validate_plant.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {
namespace {

// Error(InvalidInput) "KEY<what>", naming the matrix by its key path.
[[noreturn]] void fail(const std::string& key, const std::string& what) {
  throw Error(ErrorCode::InvalidInput, key + what, key);
}

std::string dims(const Eigen::MatrixXd& M) {
  return std::to_string(M.rows()) + "x" + std::to_string(M.cols());
}

void require_nonempty(const Eigen::MatrixXd& M, const std::string& name, const char* what) {
  if (M.rows() == 0 || M.cols() == 0)
    fail(name, ": must not be empty (" + std::string(what) + "), got " + dims(M));
}

void require_rows(const Eigen::MatrixXd& M, const std::string& name, Eigen::Index rows,
                  const char* source) {
  if (M.rows() != rows)
    fail(name, ": expected " + std::to_string(rows) + " rows (" + source + "), got " +
         std::to_string(M.rows()));
}

void require_cols(const Eigen::MatrixXd& M, const std::string& name, Eigen::Index cols,
                  const char* source) {
  if (M.cols() != cols)
    fail(name, ": expected " + std::to_string(cols) + " columns (" + source + "), got " +
         std::to_string(M.cols()));
}

void require_finite(const Eigen::MatrixXd& M, const std::string& name) {
  for (Eigen::Index j = 0; j < M.cols(); ++j)
    for (Eigen::Index i = 0; i < M.rows(); ++i)
      if (!std::isfinite(M(i, j)))
        fail(name, ": entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) +
             ") = " + number_text(M(i, j)) + " is not finite");
}

}  // namespace

void validate_plant(const Plant& plant) {
  const Eigen::MatrixXd& A = plant.A;
  require_nonempty(A, "system.A", "n >= 1");
  if (A.rows() != A.cols())
    fail("system.A", ": must be square (n x n), got " + dims(A));
  const Eigen::Index n = A.rows();

  require_rows(plant.B, "system.B", n, "n from A");
  require_nonempty(plant.B, "system.B", "p >= 1 noise inputs");
  require_cols(plant.C, "system.C", n, "n from A");
  require_nonempty(plant.C, "system.C", "m >= 1 measurements");
  require_rows(plant.D, "system.D", plant.C.rows(), "m from C");
  require_nonempty(plant.D, "system.D", "q >= 1 noise inputs");
  require_cols(plant.L, "system.L", n, "n from A");
  require_nonempty(plant.L, "system.L", "l >= 1 estimated signals");

  const bool has_H = plant.H.size() > 0;
  const bool has_E = plant.E.size() > 0;
  if (has_H && !has_E)
    fail("uncertainty.H", " is given (" + dims(plant.H) + ") but uncertainty.E is empty: "
         "Delta A = H F E needs both");
  if (has_E && !has_H)
    fail("uncertainty.E", " is given (" + dims(plant.E) + ") but uncertainty.H is empty: "
         "Delta A = H F E needs both");
  if (has_H) {
    require_rows(plant.H, "uncertainty.H", n, "n from A");
    require_cols(plant.E, "uncertainty.E", n, "n from A");
  }

  require_finite(A, "system.A");
  require_finite(plant.B, "system.B");
  require_finite(plant.C, "system.C");
  require_finite(plant.D, "system.D");
  require_finite(plant.L, "system.L");
  require_finite(plant.H, "uncertainty.H");
  require_finite(plant.E, "uncertainty.E");
}

}  // namespace hinf::synth
