// The Hill/CW plant of SPEC §3 and its discretisations (see hill_model.hpp).
#include "hinf/synth/validate_plant.hpp"
#include "hinf/synth/hill_model.hpp"

#include <cmath>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

#include "hinf/common/number_text.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {
namespace {

using Eigen::MatrixXd;

[[noreturn]] void fail(const std::string& message) {
  throw Error(ErrorCode::InvalidInput, message);
}

std::string dims(const MatrixXd& M) {
  return std::to_string(M.rows()) + "x" + std::to_string(M.cols());
}

void require_positive(const char* key, double v, const char* unit) {
  if (!std::isfinite(v) || !(v > 0))
    fail(std::string(key) + " = " + number_text(v) + ": must be finite and > 0 (" + unit + ")");
}

void require_finite_entries(const MatrixXd& M, const std::string& key) {
  for (Eigen::Index j = 0; j < M.cols(); ++j)
    for (Eigen::Index i = 0; i < M.rows(); ++i)
      if (!std::isfinite(M(i, j)))
        fail(key + ": entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) +
             ") = " + number_text(M(i, j)) + " is not finite");
}

// C and L default to the paper's [I₃ 0₃] and I₆ (SPEC §3 table).
MatrixXd measurement_matrix(const HillModel& model) {
  if (model.C.size() > 0) return model.C;
  MatrixXd C = MatrixXd::Zero(3, 6);
  C.leftCols(3).setIdentity();
  return C;
}

MatrixXd estimated_signal_matrix(const HillModel& model) {
  return model.L.size() > 0 ? model.L : MatrixXd::Identity(6, 6);
}

MatrixXd control_gain(const HillModel& model) {
  return model.K.size() > 0 ? model.K : MatrixXd::Zero(3, 6);
}

// A_c(ω) = A₁(ω) + G₀K, the continuous closed loop (SPEC §3, eqs. 1 and 3).
MatrixXd closed_loop_A(const HillModel& model, double omega) {
  return hill_continuous_A(omega) + hill_input_matrix(model.chaser_mass) * control_gain(model);
}

}  // namespace

MatrixXd hill_continuous_A(double omega) {
  MatrixXd A1 = MatrixXd::Zero(6, 6);
  A1.topRightCorner(3, 3).setIdentity();
  // A₂₁ = diag(3ω², 0, −ω²)
  A1(3, 0) = 3 * omega * omega;
  A1(5, 2) = -omega * omega;
  // A₂₂ = [0 2ω 0; −2ω 0 0; 0 0 0]
  A1(3, 4) = 2 * omega;
  A1(4, 3) = -2 * omega;
  return A1;
}

MatrixXd hill_input_matrix(double chaser_mass) {
  MatrixXd G0 = MatrixXd::Zero(6, 3);
  G0.bottomRows(3).diagonal().setConstant(1.0 / chaser_mass);
  return G0;
}

MatrixXd hill_uncertainty_H_a(double orbital_rate) {
  MatrixXd Ha = MatrixXd::Zero(6, 6);
  Ha(3, 0) = 3 * orbital_rate;  // H_a(4,1) = 3ω₀
  Ha(3, 4) = 2;                 // H_a(4,5) = 2
  Ha(4, 3) = -2;                // H_a(5,4) = −2
  Ha(5, 2) = -orbital_rate;     // H_a(6,3) = −ω₀
  return Ha;
}

MatrixXd hill_uncertainty_E_a(double orbital_rate, double delta_bar) {
  const double quadratic = orbital_rate * (2 * delta_bar + delta_bar * delta_bar);
  const double linear = orbital_rate * delta_bar;  // SPEC §3: ω₀δ̄, not the paper's ω₀δ
  Eigen::VectorXd d(6);
  d << quadratic, 0, quadratic, linear, linear, 0;
  return d.asDiagonal();
}

MatrixXd hill_uncertainty_F(double delta, double delta_bar) {
  if (!std::isfinite(delta_bar) || !(delta_bar > 0))
    fail("hill_uncertainty_F: delta_bar = " + number_text(delta_bar) + ": must be > 0");
  if (!std::isfinite(delta) || std::abs(delta) > delta_bar)
    fail("hill_uncertainty_F: delta = " + number_text(delta) + ": must satisfy |delta| <= " +
         number_text(delta_bar));
  const double c = (2 * delta + delta * delta) / (2 * delta_bar + delta_bar * delta_bar);
  const double r = delta / delta_bar;
  Eigen::VectorXd d(6);
  d << c, 0, c, r, r, 0;
  return d.asDiagonal();
}

void validate_hill_model(const HillModel& model) {
  require_positive("hill.orbital_rate", model.orbital_rate, "rad/s");
  require_positive("hill.chaser_mass", model.chaser_mass, "kg");
  require_positive("hill.sample_time", model.sample_time, "s");
  if (!std::isfinite(model.delta_bar) || model.delta_bar < 0 || model.delta_bar >= 10)
    fail("hill.delta_bar = " + number_text(model.delta_bar) +
         ": must be in [0, 10) (relative uncertainty of the orbital rate)");

  if (model.K.size() > 0 && (model.K.rows() != 3 || model.K.cols() != 6))
    fail("hill.K: expected 3x6 (3 thrust axes x 6 states), got " + dims(model.K));
  require_finite_entries(model.K, "hill.K");

  if (model.B.rows() != 6 || model.B.cols() < 1)
    fail("hill.B: expected 6 rows (the Hill state) and at least 1 column, got " + dims(model.B));
  require_finite_entries(model.B, "hill.B");

  const MatrixXd C = measurement_matrix(model);
  if (C.cols() != 6 || C.rows() < 1)
    fail("hill.C: expected 6 columns (the Hill state) and at least 1 row, got " + dims(C));
  require_finite_entries(C, "hill.C");

  if (model.D.rows() != C.rows() || model.D.cols() < 1)
    fail("hill.D: expected " + std::to_string(C.rows()) +
         " rows (m from hill.C) and at least 1 column, got " + dims(model.D));
  require_finite_entries(model.D, "hill.D");

  const MatrixXd L = estimated_signal_matrix(model);
  if (L.cols() != 6 || L.rows() < 1)
    fail("hill.L: expected 6 columns (the Hill state) and at least 1 row, got " + dims(L));
  require_finite_entries(L, "hill.L");
}

Plant build_hill_plant(const HillModel& model) {
  validate_hill_model(model);
  const double T = model.sample_time;
  const MatrixXd Ac = closed_loop_A(model, model.orbital_rate);

  Plant plant;
  MatrixXd input_integral;  // maps ΔA₁ into the discrete ΔA
  if (model.discretisation == HillModel::Discretisation::Euler) {
    plant.A = MatrixXd::Identity(6, 6) + T * Ac;  // SPEC §3: A = I + T(A₁ + G₀K)
    input_integral = T * MatrixXd::Identity(6, 6);  // ΔA = T·ΔA₁
  } else {
    // exp(T [A_c I; 0 0]) = [e^{T A_c}  ∫₀ᵀ e^{A_c s} ds; 0 I]
    MatrixXd M = MatrixXd::Zero(12, 12);
    M.topLeftCorner(6, 6) = Ac;
    M.topRightCorner(6, 6).setIdentity();
    const MatrixXd expM = (T * M).exp();
    plant.A = expM.topLeftCorner(6, 6);
    input_integral = expM.topRightCorner(6, 6);
  }
  plant.B = model.B;
  plant.C = measurement_matrix(model);
  plant.D = model.D;
  plant.L = estimated_signal_matrix(model);
  if (model.delta_bar > 0) {
    plant.H = input_integral * hill_uncertainty_H_a(model.orbital_rate);  // H = T·H_a (euler)
    plant.E = hill_uncertainty_E_a(model.orbital_rate, model.delta_bar);  // E = E_a
  } else {
    plant.H = MatrixXd::Zero(6, 0);
    plant.E = MatrixXd::Zero(0, 6);
  }
  validate_plant(plant);
  return plant;
}

MatrixXd hill_exact_discrete_A(const HillModel& model, double delta) {
  validate_hill_model(model);
  if (!std::isfinite(delta))
    fail("hill_exact_discrete_A: delta = " + number_text(delta) + ": must be finite");
  const double T = model.sample_time;
  const MatrixXd Ac = closed_loop_A(model, model.orbital_rate * (1 + delta));
  if (model.discretisation == HillModel::Discretisation::Euler)
    return MatrixXd::Identity(6, 6) + T * Ac;
  return (T * Ac).exp();
}

}  // namespace hinf::synth
