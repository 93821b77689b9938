// Hill / Clohessy-Wiltshire relative motion, SPEC §3 (seed 000 eq. 1 with its misprints
// corrected). State x = [x, y, z, xdot, ydot, zdot] (x radial, z orbit normal), thrust
// u = [F_x, F_y, F_z] in N:
//
//     xddot = 3 w^2 x + 2 w ydot + F_x/m,   yddot = -2 w xdot + F_y/m,   zddot = -w^2 z + F_z/m
//
//     A_1 = [0 I; A_21 A_22], A_21 = diag(3w^2, 0, -w^2), A_22 = [0 2w 0; -2w 0 0; 0 0 0]
//     G_0 = [0_3x3; I_3/m]
//
// With a known orbit-control law u = K x (eq. 3) the continuous closed loop is
// A_c = A_1 + G_0 K; an external thrust u_ext enters through G_0 in addition:
//     xdot = A_c x + G_0 u_ext.
// Discretisation with sample time T (computed once, at construction):
//   Euler (the paper's):  A = I + T A_c,           G = T G_0
//   ZeroOrderHold (exact): [A G; 0 I] = exp([A_c G_0; 0 0] T)
// Process function f(x, u) = A x + G u, Jacobian F = A (the model is linear).
#pragma once

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <stdexcept>
#include <string>

namespace hinf::models {

enum class Discretisation { Euler, ZeroOrderHold };

class HillModel {
 public:
  static constexpr int NX = 6;
  static constexpr int NU = 3;
  using State = Eigen::Matrix<double, 6, 1>;
  using Input = Eigen::Matrix<double, 3, 1>;
  using StateMatrix = Eigen::Matrix<double, 6, 6>;
  using InputMatrix = Eigen::Matrix<double, 6, 3>;
  using Gain = Eigen::Matrix<double, 3, 6>;

  // No orbit control (K = 0). Throws std::invalid_argument on invalid parameters.
  HillModel(double orbital_rate, double mass, double sample_time,
            Discretisation discretisation = Discretisation::Euler)
      : HillModel(orbital_rate, mass, sample_time, Gain::Zero(), discretisation) {}

  // Orbit control u = K x included in the dynamics.
  HillModel(double orbital_rate, double mass, double sample_time, const Gain& K,
            Discretisation discretisation = Discretisation::Euler)
      : w_(orbital_rate), m_(mass), T_(sample_time), K_(K), disc_(discretisation) {
    if (!std::isfinite(w_) || w_ < 0.0)
      throw std::invalid_argument("HillModel: orbital_rate must be finite and >= 0 rad/s; got " + std::to_string(w_));
    if (!std::isfinite(m_) || m_ <= 0.0)
      throw std::invalid_argument("HillModel: mass must be finite and > 0 kg; got " + std::to_string(m_));
    if (!std::isfinite(T_) || T_ <= 0.0)
      throw std::invalid_argument("HillModel: sample_time must be finite and > 0 s; got " + std::to_string(T_));
    if (!K_.allFinite()) throw std::invalid_argument("HillModel: K (3x6) has a non-finite entry");

    A_1_ = A1(w_);
    G_0_ = G0(m_);
    A_c_ = A_1_ + G_0_ * K_;
    if (disc_ == Discretisation::Euler) {
      A_ = StateMatrix::Identity() + T_ * A_c_;
      G_ = T_ * G_0_;
    } else {
      Eigen::Matrix<double, 9, 9> Mc = Eigen::Matrix<double, 9, 9>::Zero();
      Mc.topLeftCorner<6, 6>() = A_c_ * T_;
      Mc.topRightCorner<6, 3>() = G_0_ * T_;
      const Eigen::Matrix<double, 9, 9> Md = Mc.exp();
      A_ = Md.topLeftCorner<6, 6>();
      G_ = Md.topRightCorner<6, 3>();
    }
  }

  // Continuous-time matrices of SPEC §3.
  static StateMatrix A1(double w) {
    StateMatrix A = StateMatrix::Zero();
    A.topRightCorner<3, 3>().setIdentity();
    A(3, 0) = 3.0 * w * w;
    A(5, 2) = -w * w;
    A(3, 4) = 2.0 * w;
    A(4, 3) = -2.0 * w;
    return A;
  }
  static InputMatrix G0(double m) {
    InputMatrix G = InputMatrix::Zero();
    G.bottomRows<3>() = Eigen::Matrix3d::Identity() / m;
    return G;
  }

  // Continuous dynamics xdot = A_c x + G_0 u (u = external thrust, N).
  State xdot(const State& x, const Input& u) const { return A_c_ * x + G_0_ * u; }

  // Discrete process function and its Jacobian.
  State f(const State& x, const Input& u) const { return A_ * x + G_ * u; }
  const StateMatrix& F(const State& /*x*/, const Input& /*u*/) const { return A_; }

  const StateMatrix& A() const { return A_; }    // discrete state matrix
  const InputMatrix& G() const { return G_; }    // discrete thrust input matrix
  const StateMatrix& A_c() const { return A_c_; }  // A_1 + G_0 K
  const StateMatrix& A_1() const { return A_1_; }
  const InputMatrix& G_0() const { return G_0_; }
  const Gain& K() const { return K_; }
  double orbital_rate() const { return w_; }
  double mass() const { return m_; }
  double sample_time() const { return T_; }
  Discretisation discretisation() const { return disc_; }

 private:
  double w_, m_, T_;
  Gain K_;
  Discretisation disc_;
  StateMatrix A_1_, A_c_, A_;
  InputMatrix G_0_, G_;
};

}  // namespace hinf::models
