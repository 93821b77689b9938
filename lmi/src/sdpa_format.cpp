#include "hinf/lmi/sdpa_format.hpp"

#include "hinf/common/number_text.hpp"

#include <sstream>

namespace hinf::lmi {

namespace {
// Shortest text that reads back to the same double (an SDPA reader's strtod is exact).
std::string num(double v) { return hinf::number_text(v); }
}  // namespace

std::string to_sdpa_sparse(const LmiProblem& lmi, const Eigen::VectorXd& c,
                           const std::string& comment) {
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "* " << line << "\n";
  out << lmi.num_params() << " = mDIM\n1 = nBLOCK\n" << lmi.order() << " = bLOCKsTRUCT\n";
  for (int i = 0; i < c.size(); ++i) out << (i ? " " : "") << num(c(i));
  out << "\n";
  const Eigen::MatrixXd& M0 = lmi.constant();
  for (int col = 0; col < M0.cols(); ++col)
    for (int row = 0; row <= col; ++row)
      if (M0(row, col) != 0.0)
        out << "0 1 " << row + 1 << " " << col + 1 << " " << num(M0(row, col)) << "\n";
  for (const SparseEntry& e : lmi.sparse_entries())
    out << e.param + 1 << " 1 " << e.row + 1 << " " << e.col + 1 << " " << num(-e.value) << "\n";
  return out.str();
}

}  // namespace hinf::lmi
