// LAPACK QZ wrappers (DGGEV, DGGES); see qz.hpp.
#include "qz.hpp"

#include <cstddef>
#include <string>
#include <vector>

#include "hinf/common/error.hpp"

extern "C" {
// Fortran LAPACK, reference interface (LOGICAL = int; hidden CHARACTER lengths last).
using hinf_lapack_select3 = int (*)(const double*, const double*, const double*);
void dggev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda,
            double* b, const int* ldb, double* alphar, double* alphai, double* beta,
            double* vl, const int* ldvl, double* vr, const int* ldvr, double* work,
            const int* lwork, int* info, std::size_t, std::size_t);
void dgges_(const char* jobvsl, const char* jobvsr, const char* sort,
            hinf_lapack_select3 selctg, const int* n, double* a, const int* lda, double* b,
            const int* ldb, int* sdim, double* alphar, double* alphai, double* beta,
            double* vsl, const int* ldvsl, double* vsr, const int* ldvsr, double* work,
            const int* lwork, int* bwork, int* info, std::size_t, std::size_t, std::size_t);
}

namespace hinf::certify::detail {
namespace {

void check_pencil(const Eigen::MatrixXd& M, const Eigen::MatrixXd& N, const char* who) {
  if (M.rows() != M.cols() || N.rows() != N.cols() || M.rows() != N.rows())
    throw Error(ErrorCode::InvalidInput, std::string(who) + ": pencil matrices must be square and of equal size");
  if (!M.allFinite() || !N.allFinite())
    throw Error(ErrorCode::NumericalFailure, std::string(who) + ": non-finite entry in pencil");
}

// SELCTG for DGGES: eigenvalue strictly inside the unit circle.
int inside_unit_circle(const double* alphar, const double* alphai, const double* beta) {
  const double a2 = (*alphar) * (*alphar) + (*alphai) * (*alphai);
  return a2 < (*beta) * (*beta) ? 1 : 0;
}

}  // namespace

PencilEigenvalues pencil_eigenvalues(const Eigen::MatrixXd& M, const Eigen::MatrixXd& N) {
  check_pencil(M, N, "pencil_eigenvalues");
  const int n = static_cast<int>(M.rows());
  PencilEigenvalues out;
  out.alpha.resize(n);
  out.beta.resize(n);
  if (n == 0) return out;
  Eigen::MatrixXd a = M, b = N;
  Eigen::VectorXd alphar(n), alphai(n), beta(n);
  double dummy = 0, work_query = 0;
  const int one = 1;
  int lwork = -1, info = 0;
  dggev_("N", "N", &n, a.data(), &n, b.data(), &n, alphar.data(), alphai.data(), beta.data(),
         &dummy, &one, &dummy, &one, &work_query, &lwork, &info, 1, 1);
  lwork = static_cast<int>(work_query);
  std::vector<double> work(static_cast<std::size_t>(lwork > 1 ? lwork : 1));
  dggev_("N", "N", &n, a.data(), &n, b.data(), &n, alphar.data(), alphai.data(), beta.data(),
         &dummy, &one, &dummy, &one, work.data(), &lwork, &info, 1, 1);
  if (info != 0)
    throw Error(ErrorCode::NumericalFailure,
                "QZ eigenvalue computation (LAPACK DGGEV) failed, INFO = " + std::to_string(info));
  for (int i = 0; i < n; ++i) out.alpha(i) = {alphar(i), alphai(i)};
  out.beta = beta;
  return out;
}

OrderedQz ordered_qz_stable_first(const Eigen::MatrixXd& M, const Eigen::MatrixXd& N) {
  check_pencil(M, N, "ordered_qz_stable_first");
  const int n = static_cast<int>(M.rows());
  OrderedQz out;
  out.Z = Eigen::MatrixXd::Identity(n, n);
  out.alpha.resize(n);
  out.beta.resize(n);
  if (n == 0) return out;
  Eigen::MatrixXd a = M, b = N, vsl(1, 1), vsr(n, n);
  Eigen::VectorXd alphar(n), alphai(n), beta(n);
  std::vector<int> bwork(static_cast<std::size_t>(n));
  const int one = 1;
  int sdim = 0, info = 0, lwork = -1;
  double work_query = 0;
  dgges_("N", "V", "S", &inside_unit_circle, &n, a.data(), &n, b.data(), &n, &sdim,
         alphar.data(), alphai.data(), beta.data(), vsl.data(), &one, vsr.data(), &n,
         &work_query, &lwork, bwork.data(), &info, 1, 1, 1);
  lwork = static_cast<int>(work_query);
  std::vector<double> work(static_cast<std::size_t>(lwork > 1 ? lwork : 1));
  dgges_("N", "V", "S", &inside_unit_circle, &n, a.data(), &n, b.data(), &n, &sdim,
         alphar.data(), alphai.data(), beta.data(), vsl.data(), &one, vsr.data(), &n,
         work.data(), &lwork, bwork.data(), &info, 1, 1, 1);
  if (info != 0 && info != n + 2)
    throw Error(ErrorCode::NumericalFailure,
                "ordered QZ (LAPACK DGGES) failed, INFO = " + std::to_string(info));
  out.reordering_failed = (info == n + 2);
  out.Z = vsr;
  for (int i = 0; i < n; ++i) out.alpha(i) = {alphar(i), alphai(i)};
  out.beta = beta;
  out.stable_count = sdim;
  return out;
}

}  // namespace hinf::certify::detail
