// Thin Ipopt adapter: one centring step of the barrier method, i.e. the unconstrained
// minimisation of LogDetBarrier::f_t by Ipopt's Newton iteration with exact gradient and
// dense Hessian (lower triangle). Ipopt stops when our Newton-decrement criterion is
// met (intermediate callback) — the affine-invariant test of barrier methods.
#pragma once
#include <Eigen/Dense>
#include <string>

#include "barrier/log_det_barrier.hpp"

namespace hinf::barrier {

struct CenteringResult {
  Eigen::VectorXd z;
  int iterations = 0;
  double lambda2 = 0;  // Newton decrement² at z (+inf if it could not be computed)
  bool centred = false;
  bool stopped_early = false;  // early-exit predicate met (phase I found s < 0)
  bool stalled = false;        // centred by the stall rule (λ² stopped falling: round-off)
  std::string ipopt_status;
};

struct CenteringOptions {
  double lambda2_tol = 2e-3;      // centred when λ² ≤ this (λ ≈ 0.045)
  double lambda2_accept = 0.0625; // ... or when λ² has stalled at or below this (λ ≤ 0.25)
  int max_iterations = 60;
  double max_cpu_time = 600;
  int stall_iterations = 4;       // λ² not halved for this many iterations: stalled
  int give_up_iterations = 8;     // ... for this many near the centre: the centring failed
  bool phase1_stop_negative = false;  // phase I: stop as soon as s < 0 at an iterate
  bool derivative_test = false;   // run Ipopt's second-order derivative test (tests only)
};

class IpoptCentering {
 public:
  IpoptCentering();
  ~IpoptCentering();
  IpoptCentering(const IpoptCentering&) = delete;
  IpoptCentering& operator=(const IpoptCentering&) = delete;

  // Minimises barrier.f_t from z0 (which must be inside the domain).
  CenteringResult run(LogDetBarrier& barrier, const Eigen::VectorXd& z0, const CenteringOptions& opt);
  static const char* version();

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace hinf::barrier
