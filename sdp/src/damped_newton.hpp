// Centring by damped Newton on the QR step (LogDetBarrier::accurate_newton): the end of
// phase II, where Ipopt, which takes the Hessian as an explicit matrix, stalls on that
// matrix's round-off (docs/design.md, "End of the path"). Nesterov's damped Newton method
// for self-concordant functions (Introductory Lectures on Convex Optimization, 2004,
// §4.1.5): z ← z + dz/(1 + λ) while λ > 1/4, which decreases f_t by at least λ − log(1 + λ)
// and stays inside the domain; full steps below, where it converges quadratically.
// While λ > 1/4 the full step and its halvings are tried first (Armijo, slope −λ²): far
// from the centre they go further than 1/(1 + λ). No line search is needed beyond that: a
// damped step that leaves the domain or does not decrease f_t can only be round-off, and
// ends the centring.
#pragma once
#include <Eigen/Dense>

#include "centering.hpp"
#include "log_det_barrier.hpp"

namespace hinf::sdp {

// Minimises barrier.f_t (phase II) from z0, inside the domain. Uses lambda2_tol,
// lambda2_accept, max_iterations, max_cpu_time and stall_iterations of opt.
CenteringResult damped_newton_centre(LogDetBarrier& barrier, const Eigen::VectorXd& z0,
                                     const CenteringOptions& opt);

}  // namespace hinf::sdp
