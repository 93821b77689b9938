// The generalised plant of output-feedback H∞ control (docs/maths.md §26), in continuous or
// discrete time, with D22 = 0:
//   ẋ (or x(k+1)) = A x + B1 w + B2 u,   z = C1 x + D11 w + D12 u,   y = C2 x + D21 w,
// w the exogenous inputs (disturbances, noise), u the control, z the performance outputs,
// y the measurements. The controller (146) and the closed loop (147) are in
// hinf/models/controller.hpp.
#pragma once
#include <Eigen/Dense>

namespace hinf {

enum class TimeDomain { Continuous, Discrete };

inline const char* to_string(TimeDomain t) { return t == TimeDomain::Discrete ? "discrete" : "continuous"; }

struct GeneralisedPlant {
  TimeDomain time = TimeDomain::Continuous;
  double sample_time = 0;  // s; discrete time only
  Eigen::MatrixXd A;    // n×n
  Eigen::MatrixXd B1;   // n×nw
  Eigen::MatrixXd B2;   // n×nu
  Eigen::MatrixXd C1;   // nz×n
  Eigen::MatrixXd C2;   // ny×n
  Eigen::MatrixXd D11;  // nz×nw
  Eigen::MatrixXd D12;  // nz×nu
  Eigen::MatrixXd D21;  // ny×nw

  int n() const { return static_cast<int>(A.rows()); }
  int nw() const { return static_cast<int>(B1.cols()); }
  int nu() const { return static_cast<int>(B2.cols()); }
  int nz() const { return static_cast<int>(C1.rows()); }
  int ny() const { return static_cast<int>(C2.rows()); }
};

// Unstructured uncertainty in the state matrix, A + H F E with any F (possibly time-varying)
// of norm ‖F‖ ≤ 1 (docs/maths.md (160)); F maps q = E x to p, which enters the state by H.
struct UncertaintyChannel {
  Eigen::MatrixXd H;  // n×p
  Eigen::MatrixXd E;  // q×n
};

}  // namespace hinf
