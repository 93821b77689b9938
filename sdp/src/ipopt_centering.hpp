// Thin Ipopt adapter: one centring step of the barrier method, i.e. the unconstrained
// minimisation of LogDetBarrier::f_t by Ipopt's Newton iteration with exact gradient and
// dense Hessian (lower triangle). Ipopt stops when our Newton-decrement criterion is
// met (intermediate callback) — the affine-invariant test of barrier methods.
#pragma once
#include <Eigen/Dense>

#include "centering.hpp"
#include "log_det_barrier.hpp"

namespace hinf::sdp {

class IpoptCentering {
 public:
  IpoptCentering();
  ~IpoptCentering();
  IpoptCentering(const IpoptCentering&) = delete;
  IpoptCentering& operator=(const IpoptCentering&) = delete;

  // Minimises barrier.f_t from z0 (which must be inside the domain).
  CenteringResult run(LogDetBarrier& barrier, const Eigen::VectorXd& z0, const CenteringOptions& opt);

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace hinf::sdp
