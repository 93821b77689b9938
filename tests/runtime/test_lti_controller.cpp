// The flying controller (runtime/lti_controller.hpp) against the recursion written out.
#include <gtest/gtest.h>

#include "hinf/runtime/lti_controller.hpp"

namespace {

TEST(LtiController, StepIsOutputThenState) {
  Eigen::MatrixXd A(2, 2), B(2, 1), C(1, 2), D(1, 1);
  A << 1.1, 0.2, -0.3, 0.9;  // unstable: allowed for a controller
  B << 1, 2;
  C << 0.5, -1;
  D << 0.25;
  hinf::runtime::LtiController k(A, B, C, D);
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  for (int i = 0; i < 20; ++i) {
    Eigen::VectorXd e(1);
    e << std::sin(0.3 * i);
    const double u_expected = (C * x)(0) + D(0, 0) * e(0);
    x = A * x + B * e;
    EXPECT_DOUBLE_EQ(k.step(e)(0), u_expected) << i;
  }
  EXPECT_LE((k.state() - x).norm(), 1e-15 * x.norm());
}

TEST(LtiController, RefusesInconsistentShapes) {
  EXPECT_THROW(hinf::runtime::LtiController(Eigen::MatrixXd::Zero(2, 3), Eigen::MatrixXd::Zero(2, 1),
                                            Eigen::MatrixXd::Zero(1, 2), Eigen::MatrixXd::Zero(1, 1)),
               std::invalid_argument);
  EXPECT_THROW(hinf::runtime::LtiController(Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Zero(2, 1),
                                            Eigen::MatrixXd::Zero(1, 2), Eigen::MatrixXd::Zero(2, 1)),
               std::invalid_argument);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2, 2);
  A(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(hinf::runtime::LtiController(A, Eigen::MatrixXd::Zero(2, 1), Eigen::MatrixXd::Zero(1, 2),
                                            Eigen::MatrixXd::Zero(1, 1)),
               std::invalid_argument);
}

}  // namespace
