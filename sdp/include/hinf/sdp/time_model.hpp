// The solver's time model: the wall time of one Newton iteration from the work counted in
// the LMI's structure, and of a whole solve from the range of Newton iterations measured,
// so that `solve -v` can say before it starts roughly how long it will take
// (docs/benchmarks.md, "Time"). Per Newton iteration the solver
//   - assembles the barrier Hessian: lmi::LmiProblem::hessian_multiply_adds(), counted
//     from the terms' shapes;
//   - factorises the p×p Newton system twice (its own LDLᵀ for the Newton decrement, and
//     MUMPS inside Ipopt): p³/3 multiply-adds each;
//   - copies and hands over that matrix entry by entry (the Hessian's symmetrisation and
//     contraction, Ipopt's triplets): a cost per entry, p².
// The three rates were fitted (least squares of the relative error) on the development
// machine (2 cores, Debian's reference BLAS, one core per solve) to 16 solves: the random
// plants of scripts/bench-synth, n = 6 … 24, seeds 1 and 2, and two in observer form;
// predicted / measured time per Newton iteration 0.64–1.20 there, and on plants held out
// of the fit as docs/benchmarks.md "Time" says. A different machine or BLAS scales all
// three. The total is an order of magnitude, not a promise: the number of Newton
// iterations is not known before the solve.
#pragma once

namespace hinf::sdp {

// Seconds per multiply-add of the Hessian assembly and of the factorisations, and per
// entry of the Newton matrix.
constexpr double kSecondsPerHessianMultiplyAdd = 1.2e-10;
constexpr double kSecondsPerFactorMultiplyAdd = 3.0e-10;
constexpr double kSecondsPerNewtonEntry = 8.1e-8;
// Newton iterations of the solves measured in docs/benchmarks.md and the golden files:
// the range the per-iteration time is multiplied by.
constexpr int kFewestNewtonIterations = 35;
constexpr int kMostNewtonIterations = 160;

struct TimeEstimate {
  double newton_iteration_s = 0;  // one Newton iteration
  double fewest_s = 0, most_s = 0;  // the whole solve, kFewest… and kMost… iterations
};

// The estimate for an LMI whose Hessian costs `hessian_multiply_adds` in `params` variables.
TimeEstimate estimated_solve_time(double hessian_multiply_adds, long params);

}  // namespace hinf::sdp
