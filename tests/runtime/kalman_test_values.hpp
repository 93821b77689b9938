// Values shared by the Kalman-filter tests (test_ekf.cpp, test_rekf.cpp): the relative
// difference they compare with, and the process noise of seed 000's navigation filter.
#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace hinf::test {

// ||a - b|| / max(1, ||b||) in the Frobenius norm.
inline double rel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / std::max(1.0, b.norm());
}

// diag(0.05², 0.05², 0.05², 0.001², 0.001², 0.001²): the paper's Q of the Hill-model EKF.
inline Eigen::Matrix<double, 6, 6> paper_Q() {
  Eigen::Matrix<double, 6, 1> b;
  b << 0.05, 0.05, 0.05, 0.001, 0.001, 0.001;
  return (b.array() * b.array()).matrix().asDiagonal();
}

}  // namespace hinf::test
