// A discrete-time state-space system x(k+1) = A x + B u, y = C x + D u.
#pragma once
#include <Eigen/Dense>

namespace hinf {

struct StateSpace {
  Eigen::MatrixXd A;  // n×n
  Eigen::MatrixXd B;  // n×p
  Eigen::MatrixXd C;  // l×n
  Eigen::MatrixXd D;  // l×p
};

}  // namespace hinf
