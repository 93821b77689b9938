// A discrete-time LTI controller as it flies (docs/maths.md (146) in discrete time):
//
//     u(k)      = C_K x_K(k) + D_K e(k)
//     x_K(k+1)  = A_K x_K(k) + B_K e(k)
//
// e(k) the controller's input (the measurement minus its set point), u(k) its output.
// step(e(k)) returns u(k) and then advances the state, in that order. Dimensions are known
// at run time (a controller file); every buffer is allocated at construction and step()
// does not allocate. Unlike a filter's A_F, A_K need not be stable (a controller of an
// unstable plant may be unstable itself), so construction checks shapes and finiteness only
// and throws std::invalid_argument naming the matrix. Needs Eigen only.
#pragma once

#include <Eigen/Dense>

#include <stdexcept>
#include <string>

namespace hinf::runtime {

class LtiController {
 public:
  LtiController(Eigen::MatrixXd A_K, Eigen::MatrixXd B_K, Eigen::MatrixXd C_K, Eigen::MatrixXd D_K)
      : A_(std::move(A_K)), B_(std::move(B_K)), C_(std::move(C_K)), D_(std::move(D_K)) {
    const Eigen::Index n = A_.rows();
    require(A_.cols() == n, "A_K must be square");
    require(B_.rows() == n, "B_K must have as many rows as A_K");
    require(C_.cols() == n, "C_K must have as many columns as A_K");
    require(D_.rows() == C_.rows() && D_.cols() == B_.cols(), "D_K must be (rows of C_K) x (columns of B_K)");
    require(A_.allFinite() && B_.allFinite() && C_.allFinite() && D_.allFinite(), "a gain matrix has a non-finite entry");
    x_ = Eigen::VectorXd::Zero(n);
    x_next_ = Eigen::VectorXd::Zero(n);
    u_ = Eigen::VectorXd::Zero(C_.rows());
  }

  Eigen::Index inputs() const { return B_.cols(); }
  Eigen::Index outputs() const { return C_.rows(); }
  const Eigen::VectorXd& state() const { return x_; }
  void reset() { x_.setZero(); }

  // u(k) for the input e(k) (size inputs()); the reference stays valid until the next step.
  const Eigen::VectorXd& step(const Eigen::VectorXd& e) {
    u_.noalias() = C_ * x_;
    u_.noalias() += D_ * e;
    x_next_.noalias() = A_ * x_;
    x_next_.noalias() += B_ * e;
    x_.swap(x_next_);
    return u_;
  }

 private:
  static void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("LtiController: " + what);
  }
  Eigen::MatrixXd A_, B_, C_, D_;
  Eigen::VectorXd x_, x_next_, u_;
};

}  // namespace hinf::runtime
