#include "ipopt_centering.hpp"

#include "hinf/sdp/path_following.hpp"

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>
#include <IpoptConfig.h>

#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

namespace hinf::sdp {

namespace {

using Ipopt::Index;
using Ipopt::Number;

// Bounds beyond Ipopt's nlp_lower/upper_bound_inf (±1e19): the variables are free.
constexpr Number kFreeBound = 1e20;
// λ² counts as progress when it falls below this fraction of the best so far.
constexpr double kCentringProgressFactor = 0.5;
// The exact-Newton bound λ₊ ≤ (λ/(1 − λ))² is tested on full steps taken from
// λ² < kQuadraticRegionLambda2 (λ < 1/2), and broken when λ₊² exceeds it this many times.
constexpr double kQuadraticRegionLambda2 = 0.25;
constexpr double kNewtonBoundSlack = 4.0;
// Giving up: no progress for give_up_iterations while λ² < kNearCentreLambda2, or
// while the Hessian has turned numerically indefinite kIndefiniteLimit times since the last
// progress (far from the centre, in Newton's damped stage, λ² may stay large for many steps
// while the barrier falls: COMPleib's NN11 starts with four indefinite Hessians, then λ² ≈ 55
// for 13 steps while s falls from 0.38 to below 0).
constexpr double kNearCentreLambda2 = 1.0;
constexpr int kIndefiniteLimit = 2;
// Ipopt's own convergence tests are set below anything reachable: the Newton-decrement
// test of the intermediate callback ends every centring.
constexpr Number kIpoptTolerance = 1e-14;
// Ipopt refuses max_cpu_time <= 0; a centring without time left gets this (s). Ipopt
// 3.11 counts CPU time only (no max_wall_time), which falls behind the wall clock on a
// busy machine: the intermediate callback also ends the centring on the wall clock.
constexpr Number kMinimumCpuTime = 1e-3;
// Ipopt's derivative checker (tests only): forward-difference step and relative tolerance.
constexpr Number kDerivativeTestPerturbation = 1e-7;
constexpr Number kDerivativeTestTolerance = 1e-5;
constexpr Number kIpoptDefaultPerturbationRadius = 10.0;
// MUMPS's workspace over-allocation (%): the Newton matrix is dense, and the default
// 1000 % (zeroed at every factorisation) costs more than the factorisation itself.
constexpr Index kMumpsMemPercent = 10;

class CenteringTnlp : public Ipopt::TNLP {
 public:
  CenteringTnlp(LogDetBarrier& b, const Eigen::VectorXd& z0, const CenteringOptions& o)
      : barrier_(b), z0_(z0), opt_(o), n_(b.dim()) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = n_;
    m = 0;
    nnz_jac_g = 0;
    nnz_h_lag = n_ * (n_ + 1) / 2;  // dense lower triangle
    index_style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index, Number*, Number*) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = -kFreeBound;
      x_u[i] = kFreeBound;
    }
    return true;
  }
  bool get_starting_point(Index n, bool, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    for (Index i = 0; i < n; ++i) x[i] = z0_(i);
    return true;
  }
  bool eval_f(Index n, const Number* x, bool, Number& f) override {
    return barrier_.value(Eigen::Map<const Eigen::VectorXd>(x, n), f);
  }
  bool eval_grad_f(Index n, const Number* x, bool, Number* g) override {
    const Eigen::Map<const Eigen::VectorXd> z(x, n);
    if (!barrier_.gradient(z, grad_)) return false;
    last_grad_z_ = z;
    Eigen::Map<Eigen::VectorXd>(g, n) = grad_;
    return true;
  }
  bool eval_g(Index, const Number*, bool, Index, Number*) override { return true; }
  bool eval_jac_g(Index, const Number*, bool, Index, Index, Index*, Index*, Number*) override {
    return true;
  }
  bool eval_h(Index n, const Number* x, bool, Number obj_factor, Index, const Number*, bool,
              Index, Index* iRow, Index* jCol, Number* values) override {
    if (values == nullptr) {
      Index k = 0;
      for (Index i = 0; i < n; ++i)
        for (Index j = 0; j <= i; ++j) {
          iRow[k] = i;
          jCol[k] = j;
          ++k;
        }
      return true;
    }
    if (!barrier_.hessian(Eigen::Map<const Eigen::VectorXd>(x, n), hess_)) return false;
    Index k = 0;
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j <= i; ++j) values[k++] = obj_factor * hess_(i, j);
    return true;
  }
  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number, Number, Number, Number,
                             Number, Number, Number, Number alpha_pr, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    iterations_ = iter;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() > opt_.max_seconds ||
        (opt_.interrupted && opt_.interrupted())) {
      time_limited_ = true;
      return false;
    }
    if (last_grad_z_.size() != n_) return true;
    if (opt_.phase1_stop_negative && last_grad_z_(n_ - 1) < 0) {
      stopped_early_ = true;
      return false;
    }
    double l2 = 0;
    const bool definite = barrier_.newton_decrement2(last_grad_z_, l2);
    if (opt_.on_newton_step) opt_.on_newton_step(iter, definite ? l2 : std::numeric_limits<double>::quiet_NaN());
    if (!definite) {
      ++indefinite_;
      // The explicit Hessian has turned numerically indefinite: its round-off has reached
      // its smallest eigenvalues, and Ipopt's steps are no longer Newton steps.
      if (opt_.stop_on_inexact_newton) {
        inexact_ = true;
        return false;
      }
    } else {
      if (l2 <= opt_.lambda2_tol) {
        centred_ = true;
        return false;
      }
      // a full step from λ < 1/2 that broke the exact-Newton bound (CenteringOptions)
      if (opt_.stop_on_inexact_newton && alpha_pr == 1.0 && prev_lambda2_ < kQuadraticRegionLambda2) {
        const double lp = std::sqrt(prev_lambda2_), bound = std::pow(lp / (1 - lp), 4);
        if (l2 > kNewtonBoundSlack * bound) {
          inexact_ = true;
          return false;
        }
      }
      prev_lambda2_ = l2;
      // Late on the path round-off sets a floor under λ² and Newton's iterates wander
      // around it: once λ² stops falling, accept the iterate with the smallest λ² if it is
      // well inside the quadratic region (≤ lambda2_accept); the caller's gap bound
      // accounts for λ (path_following.cpp). Measured: returning that iterate rather than
      // the last one saves the retries its larger λ² caused (random n = 10: 95 → 67
      // Newton iterations, same final gap).
      if (l2 < smallest_lambda2_) {
        smallest_lambda2_ = l2;
        smallest_z_ = last_grad_z_;
      }
      if (l2 < kCentringProgressFactor * best_lambda2_) {
        best_lambda2_ = l2;
        best_iter_ = iter;
        indefinite_ = 0;
      } else if (iter - best_iter_ >= opt_.stall_iterations && smallest_lambda2_ <= opt_.lambda2_accept) {
        centred_ = true;
        stalled_ = true;
        return false;
      }
    }
    // Newton has lost to round-off when λ² has not halved for give_up_iterations while
    // near the centre, or while the Hessian keeps turning numerically indefinite
    // (gᵀH⁻¹g < 0): stop, and let the caller retry with a shorter step in t or fall
    // back to its last centred point.
    if (iter - best_iter_ >= opt_.give_up_iterations &&
        (best_lambda2_ < kNearCentreLambda2 || indefinite_ >= kIndefiniteLimit))
      return false;
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    z_ = Eigen::Map<const Eigen::VectorXd>(x, n);
  }

  LogDetBarrier& barrier_;
  Eigen::VectorXd z0_;
  CenteringOptions opt_;
  int n_;
  Eigen::VectorXd grad_, last_grad_z_, z_;
  Eigen::MatrixXd hess_;
  int iterations_ = 0;
  bool centred_ = false, stopped_early_ = false;
  double best_lambda2_ = std::numeric_limits<double>::infinity();
  double smallest_lambda2_ = std::numeric_limits<double>::infinity();  // and where
  Eigen::VectorXd smallest_z_;
  bool stalled_ = false;  // centred by the stall rule
  bool inexact_ = false;  // stopped by stop_on_inexact_newton
  double prev_lambda2_ = std::numeric_limits<double>::infinity();
  int best_iter_ = 0;
  int indefinite_ = 0;  // iterations where λ² could not be computed, since the last progress
  bool time_limited_ = false;  // stopped by the wall clock (max_seconds)
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Ipopt reports any failure of MUMPS as Error_In_Step_Computation; only its linear-algebra
// journal, at level J_ERROR, says which (MUMPS's INFO(1)). This journal keeps what those
// messages say, so that MUMPS running out of memory — INFO(1) = -13 (a Fortran ALLOCATE
// failed) or -19 (over its memory cap), or -8/-9 still after Ipopt's reallocations ("not
// able to obtain enough memory") — is told from a numerical failure.
class MumpsErrorJournal : public Ipopt::Journal {
 public:
  MumpsErrorJournal() : Ipopt::Journal("hinf-mumps-errors", Ipopt::J_NONE) {
    SetPrintLevel(Ipopt::J_LINEAR_ALGEBRA, Ipopt::J_ERROR);
  }
  void reset() { out_of_memory_ = false; }
  bool out_of_memory() const { return out_of_memory_; }

 protected:
  void PrintImpl(Ipopt::EJournalCategory, Ipopt::EJournalLevel, const char* str) override { note(str); }
  void PrintfImpl(Ipopt::EJournalCategory, Ipopt::EJournalLevel, const char* format, va_list ap) override {
    char line[kMessageChars];
    std::vsnprintf(line, sizeof line, format, ap);
    note(line);
  }
  void FlushBufferImpl() override {}

 private:
  static constexpr int kMessageChars = 512;
  void note(const std::string& message) {
    if (message.find("not able to obtain enough memory") != std::string::npos) out_of_memory_ = true;
    for (const char* key : {"INFO(1) =", "Error="}) {
      const size_t at = message.find(key);
      if (at == std::string::npos) continue;
      const int info1 = std::atoi(message.c_str() + at + std::strlen(key));
      if (info1 == kMumpsAllocateFailed || info1 == kMumpsOverMemoryCap) out_of_memory_ = true;
    }
  }
  static constexpr int kMumpsAllocateFailed = -13, kMumpsOverMemoryCap = -19;
  bool out_of_memory_ = false;
};

}  // namespace

struct IpoptCentering::Impl {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app;
  Ipopt::SmartPtr<MumpsErrorJournal> mumps_errors = new MumpsErrorJournal;
};

IpoptCentering::IpoptCentering() : impl_(new Impl) {
  impl_->app = IpoptApplicationFactory();
  auto& o = *impl_->app->Options();
  o.SetIntegerValue("print_level", 0);
  o.SetStringValue("sb", "yes");
  o.SetStringValue("hessian_approximation", "exact");
  o.SetStringValue("nlp_scaling_method", "none");  // Newton is affine invariant; we scale
  o.SetNumericValue("tol", kIpoptTolerance);  // our Newton-decrement test stops Ipopt
  o.SetNumericValue("dual_inf_tol", kIpoptTolerance);
  o.SetIntegerValue("acceptable_iter", 0);
  o.SetStringValue("linear_solver", "mumps");
  o.SetStringValue("check_derivatives_for_naninf", "no");
  o.SetIntegerValue("mumps_mem_percent", kMumpsMemPercent);
  // The matrix is the barrier Hessian (positive definite): no MUMPS scaling. Measured:
  // scaling costs time at every factorisation and, late on the path, more Newton
  // iterations (random n = 10: 127 with, 87 without; docs/benchmarks.md).
  o.SetIntegerValue("mumps_permuting_scaling", 0);
  o.SetIntegerValue("mumps_scaling", 0);
  impl_->app->Initialize("");  // never read an ipopt.opt from the working directory
  impl_->app->Jnlst()->AddJournal(Ipopt::GetRawPtr(impl_->mumps_errors));
}

IpoptCentering::~IpoptCentering() { delete impl_; }

const char* newton_engine_version() { return IPOPT_VERSION; }

CenteringResult IpoptCentering::run(LogDetBarrier& barrier, const Eigen::VectorXd& z0,
                                    const CenteringOptions& opt) {
  auto& o = *impl_->app->Options();
  o.SetIntegerValue("max_iter", opt.max_iterations);
  o.SetNumericValue("max_cpu_time", opt.max_seconds > 0 ? opt.max_seconds : kMinimumCpuTime);
  if (opt.derivative_test) {
    o.SetStringValue("derivative_test", "second-order");
    o.SetNumericValue("derivative_test_perturbation", kDerivativeTestPerturbation);
    o.SetNumericValue("derivative_test_tol", kDerivativeTestTolerance);
    // check at the given point: a random perturbation could leave the LMI cone
    o.SetNumericValue("point_perturbation_radius", 0.0);
    o.SetIntegerValue("print_level", 4);
  }
  Ipopt::SmartPtr<CenteringTnlp> tnlp = new CenteringTnlp(barrier, z0, opt);
  impl_->mumps_errors->reset();
  const Ipopt::ApplicationReturnStatus st = impl_->app->OptimizeTNLP(Ipopt::GetRawPtr(tnlp));
  if (opt.derivative_test) {
    o.SetStringValue("derivative_test", "none");
    o.SetIntegerValue("print_level", 0);
    o.SetNumericValue("point_perturbation_radius", kIpoptDefaultPerturbationRadius);
  }
  CenteringResult r;
  r.z = tnlp->z_.size() == z0.size() ? tnlp->z_ : z0;
  if (tnlp->stalled_ && tnlp->smallest_z_.size() == z0.size()) r.z = tnlp->smallest_z_;
  r.stalled = tnlp->stalled_;
  r.inexact = tnlp->inexact_;
  r.iterations = tnlp->iterations_;
  // λ² at the returned point itself (the gap bound of the caller depends on it)
  double l2 = std::numeric_limits<double>::infinity();
  r.lambda2 = barrier.newton_decrement2(r.z, l2) ? l2 : std::numeric_limits<double>::infinity();
  r.centred = tnlp->centred_;
  r.stopped_early = tnlp->stopped_early_;
  switch (st) {
    case Ipopt::Solve_Succeeded: r.status = "solve_succeeded"; break;
    case Ipopt::User_Requested_Stop: r.status = tnlp->time_limited_ ? "wall_time_limit" : "user_requested_stop"; break;
    case Ipopt::Maximum_Iterations_Exceeded: r.status = "maximum_iterations"; break;
    case Ipopt::Maximum_CpuTime_Exceeded: r.status = "maximum_cpu_time"; break;
    case Ipopt::Search_Direction_Becomes_Too_Small: r.status = "search_direction_too_small"; break;
    case Ipopt::Restoration_Failed: r.status = "restoration_failed"; break;
    case Ipopt::Error_In_Step_Computation:
      r.out_of_memory = impl_->mumps_errors->out_of_memory();
      r.status = r.out_of_memory ? "mumps_out_of_memory" : "error_in_step_computation";
      break;
    case Ipopt::Invalid_Number_Detected: r.status = "invalid_number"; break;
    case Ipopt::Insufficient_Memory: r.status = "insufficient_memory"; r.out_of_memory = true; break;
    default: r.status = "ipopt_status_" + std::to_string(static_cast<int>(st)); break;
  }
  // A successful Ipopt exit (its own tolerance met) also means centred.
  if (st == Ipopt::Solve_Succeeded || st == Ipopt::Solved_To_Acceptable_Level) r.centred = true;
  return r;
}

}  // namespace hinf::sdp
