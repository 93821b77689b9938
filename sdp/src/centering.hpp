// What a centring step of the barrier method returns, and its options; shared by the
// two engines: Ipopt (ipopt_centering.hpp, all of phase I and most of phase II) and the
// damped Newton on the QR step (damped_newton.hpp, the end of phase II).
#pragma once
#include <functional>
#include <Eigen/Dense>
#include <string>

namespace hinf::sdp {

struct CenteringResult {
  Eigen::VectorXd z;
  int iterations = 0;
  double lambda2 = 0;  // Newton decrement² at z (+inf if it could not be computed)
  bool centred = false;
  bool stopped_early = false;  // early-exit predicate met (phase I found s < 0)
  bool stalled = false;        // centred by the stall rule (λ² stopped falling: round-off)
  bool inexact = false;        // stopped: the steps broke Newton's quadratic convergence bound
  bool out_of_memory = false;  // the engine could not allocate (Ipopt's Insufficient_Memory)
  std::string status;  // how the centring ended (Ipopt's return status, or the damped Newton's)
};

struct CenteringOptions {
  double lambda2_tol = 2e-3;      // centred when λ² ≤ this (λ ≈ 0.045)
  double lambda2_accept = 0.0625; // ... or when λ² has stalled at or below this (λ ≤ 0.25)
  int max_iterations = 60;
  double max_seconds = 600;      // wall-clock budget of this centring (checked every iteration)
  std::function<bool()> interrupted;  // checked with it: true ends the centring (Options::interrupted)
  int stall_iterations = 4;       // λ² not halved for this many iterations: stalled
  int give_up_iterations = 8;     // ... for this many near the centre: the centring failed
  bool phase1_stop_negative = false;  // phase I: stop as soon as s < 0 at an iterate
  // Stop (result.inexact) when a full Newton step from λ < 1/2 gives λ₊² above 4× the bound
  // λ₊ ≤ (λ/(1 − λ))² that holds for exact Newton steps on a self-concordant function
  // (Nesterov 2004, Thm 4.1.14), or when the Hessian is found numerically indefinite
  // (gᵀH⁻¹g < 0): the steps are no longer accurate Newton steps.
  bool stop_on_inexact_newton = false;
  bool derivative_test = false;   // run Ipopt's second-order derivative test (tests only)
  // Called after every Newton iteration with its index and λ² (NaN where the explicit
  // Hessian was found indefinite), for progress output on large problems; may be empty.
  std::function<void(int newton, double lambda2)> on_newton_step;
};

}  // namespace hinf::sdp
