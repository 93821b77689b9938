// Transfer-function comparison of two filters; see filter_compare.hpp.
#include "hinf/certify/filter_compare.hpp"

#include <limits>
#include <sstream>
#include <string>

#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/stability.hpp"
#include "hinf/common/error.hpp"

namespace hinf::certify {
namespace {

void validate_filter(const Filter& f, const char* name) {
  const Eigen::Index n = f.A_F.rows();
  std::ostringstream msg;
  if (f.A_F.cols() != n || f.B_F.rows() != n || f.C_F.cols() != n)
    msg << "filter " << name << ": inconsistent dimensions (A_F " << f.A_F.rows() << "×"
        << f.A_F.cols() << ", B_F " << f.B_F.rows() << "×" << f.B_F.cols() << ", C_F "
        << f.C_F.rows() << "×" << f.C_F.cols() << ")";
  else if (f.D_F.size() > 0 && (f.D_F.rows() != f.C_F.rows() || f.D_F.cols() != f.B_F.cols()))
    msg << "filter " << name << ": D_F is " << f.D_F.rows() << "×" << f.D_F.cols() << ", expected "
        << f.C_F.rows() << "×" << f.B_F.cols();
  else if (!f.A_F.allFinite() || !f.B_F.allFinite() || !f.C_F.allFinite() || !f.D_F.allFinite())
    msg << "filter " << name << ": non-finite entry";
  if (!msg.str().empty()) throw Error(ErrorCode::InvalidInput, "compare_filters: " + msg.str());
  const double rho = spectral_radius(f.A_F);
  if (!(rho < 1.0)) {
    msg.precision(17);
    msg << "compare_filters: filter " << name << " is not Schur stable (spectral radius of A_F = "
        << rho << " >= 1); its transfer function has no H∞ norm";
    throw Error(ErrorCode::InvalidInput, msg.str());
  }
}

}  // namespace

FilterDifference compare_filters(const Filter& a, const Filter& b, double rel_tol) {
  validate_filter(a, "a");
  validate_filter(b, "b");
  if (a.B_F.cols() != b.B_F.cols() || a.C_F.rows() != b.C_F.rows())
    throw Error(ErrorCode::InvalidInput,
                "compare_filters: filters map " + std::to_string(a.B_F.cols()) + " → " +
                    std::to_string(a.C_F.rows()) + " and " + std::to_string(b.B_F.cols()) +
                    " → " + std::to_string(b.C_F.rows()) + " signals");
  const Eigen::Index na = a.A_F.rows(), nb = b.A_F.rows();
  const Eigen::Index m = a.B_F.cols(), l = a.C_F.rows();
  StateSpace diff;
  diff.A = Eigen::MatrixXd::Zero(na + nb, na + nb);
  diff.A.topLeftCorner(na, na) = a.A_F;
  diff.A.bottomRightCorner(nb, nb) = b.A_F;
  diff.B.resize(na + nb, m);
  diff.B << a.B_F, b.B_F;
  diff.C.resize(l, na + nb);
  diff.C << a.C_F, -b.C_F;
  // the feedthrough of a filtered estimate (docs/maths.md (140)); zero for a predictor
  const auto feedthrough = [&](const Filter& f) {
    return f.D_F.size() > 0 ? Eigen::MatrixXd(f.D_F) : Eigen::MatrixXd::Zero(l, m);
  };
  diff.D = feedthrough(a) - feedthrough(b);

  FilterDifference out;
  out.hinf_norm_difference = discrete_hinf_norm(diff, rel_tol).norm;
  out.reference_norm = discrete_hinf_norm(a.A_F, a.B_F, a.C_F, feedthrough(a), rel_tol).norm;
  if (out.reference_norm > 0) out.relative = out.hinf_norm_difference / out.reference_norm;
  else out.relative = out.hinf_norm_difference > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  return out;
}

}  // namespace hinf::certify
