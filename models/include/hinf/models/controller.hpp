// A full-order output-feedback controller of a generalised plant (docs/maths.md (146)),
//   ẋ_K (or x_K(k+1)) = A_K x_K + B_K y,   u = C_K x_K + D_K y,
// and the closed loop it makes (147), ξ = [x; x_K]:
//   A_cl = [A + B2 D_K C2, B2 C_K; B_K C2, A_K],   B_cl = [B1 + B2 D_K D21; B_K D21],
//   C_cl = [C1 + D12 D_K C2, D12 C_K],             D_cl = D11 + D12 D_K D21.
#pragma once
#include <Eigen/Dense>

#include "hinf/models/generalised_plant.hpp"
#include "hinf/models/state_space.hpp"

namespace hinf {

struct Controller {
  Eigen::MatrixXd A_K;  // n_K×n_K
  Eigen::MatrixXd B_K;  // n_K×ny
  Eigen::MatrixXd C_K;  // nu×n_K
  Eigen::MatrixXd D_K;  // nu×ny
};

// The closed loop (147) from w to z (a StateSpace in the plant's time domain).
inline StateSpace closed_loop(const GeneralisedPlant& P, const Controller& K) {
  const int n = P.n(), nk = static_cast<int>(K.A_K.rows());
  StateSpace cl;
  cl.A.resize(n + nk, n + nk);
  cl.A << P.A + P.B2 * K.D_K * P.C2, P.B2 * K.C_K, K.B_K * P.C2, K.A_K;
  cl.B.resize(n + nk, P.nw());
  cl.B << P.B1 + P.B2 * K.D_K * P.D21, K.B_K * P.D21;
  cl.C.resize(P.nz(), n + nk);
  cl.C << P.C1 + P.D12 * K.D_K * P.C2, P.D12 * K.C_K;
  cl.D = P.D11 + P.D12 * K.D_K * P.D21;
  return cl;
}

}  // namespace hinf
