// The uncertain discrete-time plant of docs/maths.md (1)–(4):
//   x(k+1) = (A + H F(k) E) x(k) + B w(k),  y(k) = C x(k) + D v(k),  z(k) = L x(k),
//   F(k)ᵀF(k) ≤ I.
#pragma once
#include <Eigen/Dense>
#include <string>

namespace hinf {

struct Plant {
  Eigen::MatrixXd A;  // n×n
  Eigen::MatrixXd B;  // n×p
  Eigen::MatrixXd C;  // m×n
  Eigen::MatrixXd D;  // m×q
  Eigen::MatrixXd L;  // l×n
  Eigen::MatrixXd H;  // n×j  (0 columns: no uncertainty)
  Eigen::MatrixXd E;  // k×n  (0 rows: no uncertainty)

  int n() const { return static_cast<int>(A.rows()); }
  int p() const { return static_cast<int>(B.cols()); }
  int m() const { return static_cast<int>(C.rows()); }
  int q() const { return static_cast<int>(D.cols()); }
  int l() const { return static_cast<int>(L.rows()); }
  int j() const { return static_cast<int>(H.cols()); }
  int k() const { return static_cast<int>(E.rows()); }
  bool uncertain() const { return H.size() > 0 && E.size() > 0; }
};

// The fixed-gain full-order filter of docs/maths.md (5)–(6).
struct Filter {
  Eigen::MatrixXd A_F;  // n×n
  Eigen::MatrixXd B_F;  // n×m
  Eigen::MatrixXd C_F;  // l×n
};

}  // namespace hinf
