// The solver's memory model: the peak resident size of one solve (minimize_linear and the
// verified bracket after it) from the LMI's order N and its p variables, so that a caller
// can refuse a problem that would not fit before allocating anything (docs/benchmarks.md,
// "Memory"). The largest arrays are:
//   - the barrier Hessian, its LDLᵀ workspace, Ipopt's triplets, MUMPS's copy and dense
//     factor: ~4.5·p² doubles (kHessianDoublesPerParamSquared);
//   - the QR Newton step of the end of the path and the verified bracket's projection,
//     each a matrix of up to N(N+1)/2 rows and p columns with its Householder copy:
//     2·N(N+1)·p doubles (kJacobianCopies).
#pragma once
#include <cstddef>

namespace hinf::sdp {

// Bytes of the executable, its libraries and small arrays (peak RSS at N = 37, p = 128).
constexpr double kBaseBytes = 14.0 * (1 << 20);
constexpr double kHessianDoublesPerParamSquared = 4.5;
constexpr double kJacobianCopies = 4.0;  // two matrices, each with its QR copy

// Estimated peak resident bytes of a solve of an LMI of order `order` in `params` variables.
double estimated_peak_bytes(long order, long params);

}  // namespace hinf::sdp
