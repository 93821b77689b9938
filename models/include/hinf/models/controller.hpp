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

// The bilinear (Tustin) transform of a continuous-time controller for period T
// (docs/maths.md (161)): its transfer function at z is the continuous one at
// s = (2/T)(z − 1)/(z + 1). With M = (I − A_K T/2)⁻¹:
//   A_d = M (I + A_K T/2),  B_d = T M B_K,  C_d = C_K M,  D_d = D_K + (T/2) C_K M B_K.
// Defined when no pole of the controller is at s = 2/T.
inline Controller tustin(const Controller& K, double T) {
  const Eigen::Index n = K.A_K.rows();
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(I - (T / 2) * K.A_K);
  const Eigen::MatrixXd M = lu.inverse();
  Controller d;
  d.A_K = M * (I + (T / 2) * K.A_K);
  d.B_K = T * M * K.B_K;
  d.C_K = K.C_K * M;
  d.D_K = K.D_K + (T / 2) * K.C_K * M * K.B_K;
  return d;
}

}  // namespace hinf
