// The Hill/CW plant of docs/maths.md §9.4–§9.5 and its discretisations (see hill_model.hpp).
#include "hinf/synth/validate_plant.hpp"
#include "hinf/synth/hill_plant.hpp"

#include <cmath>
#include <string>

#include "hinf/common/number_text.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {
namespace {

using Eigen::MatrixXd;
namespace hill = hinf::models::hill;

constexpr double kPi = 3.14159265358979323846;

// Error(InvalidInput) "FIELD<what>", naming the HillPlantSpec field; a reader re-keys it
// to where the field came from (Error::rekeyed). An empty field: a plain message.
[[noreturn]] void fail(const std::string& field, const std::string& what) {
  if (field.empty()) throw Error(ErrorCode::InvalidInput, what);
  throw Error::invalid_field(field, what);
}

std::string dims(const MatrixXd& M) {
  return std::to_string(M.rows()) + "x" + std::to_string(M.cols());
}

void require_positive(const char* key, double v, const char* unit) {
  if (!std::isfinite(v) || !(v > 0))
    fail(key, " = " + number_text(v) + ": must be finite and > 0 (" + unit + ")");
}

void require_finite_entries(const MatrixXd& M, const std::string& key) {
  for (Eigen::Index j = 0; j < M.cols(); ++j)
    for (Eigen::Index i = 0; i < M.rows(); ++i)
      if (!std::isfinite(M(i, j)))
        fail(key, ": entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) +
             ") = " + number_text(M(i, j)) + " is not finite");
}

// C and L default to the paper's [I₃ 0₃] and I₆ (docs/maths.md §9.8 table).
MatrixXd measurement_matrix(const HillPlantSpec& model) {
  if (model.C.size() > 0) return model.C;
  MatrixXd C = MatrixXd::Zero(3, 6);
  C.leftCols(3).setIdentity();
  return C;
}

MatrixXd estimated_signal_matrix(const HillPlantSpec& model) {
  return model.L.size() > 0 ? model.L : MatrixXd::Identity(6, 6);
}

MatrixXd control_gain(const HillPlantSpec& model) {
  return model.K.size() > 0 ? model.K : MatrixXd::Zero(3, 6);
}

// A_c(ω) = A₁(ω) + G₀K, the continuous closed loop (docs/maths.md (66)).
hill::Matrix6 closed_loop_A(const HillPlantSpec& model, double omega) {
  return hill::continuous_A(omega) + hill::input_matrix(model.chaser_mass) * control_gain(model);
}

// The discrete model must exist in floating point: a sample time so long that exp(A_c·T)
// or Γ overflows has no discrete plant, and one for which Γ·H_a vanishes would silently
// drop the uncertainty (docs/maths.md §9.5). Named by the Hill fields that set them.
void require_representable(const HillPlantSpec& model, const Plant& plant) {
  const bool finite = plant.A.allFinite() && plant.H.allFinite() && plant.E.allFinite();
  const bool lost_uncertainty = model.delta_bar > 0 && (plant.H.isZero(0.0) || plant.E.isZero(0.0));
  if (finite && !lost_uncertainty) return;
  fail("sample_time", " = " + number_text(model.sample_time) + ": the discrete Hill model at orbital_rate = " +
                          number_text(model.orbital_rate) + " rad/s " +
                          (finite ? "loses its uncertainty channel Γ·H_a (it rounds to zero)"
                                  : "is not finite (exp(A_c·T) or Γ overflows)") +
                          "; take the filter's sample period, a small fraction of the orbit period 2π/ω = " +
                          number_text(2 * kPi / model.orbital_rate) + " s (docs/maths.md §9.5)");
}

}  // namespace

MatrixXd hill_uncertainty_F(double delta, double delta_bar) {
  if (!std::isfinite(delta_bar) || !(delta_bar > 0))
    fail("", "hill_uncertainty_F: delta_bar = " + number_text(delta_bar) + ": must be > 0");
  if (!std::isfinite(delta) || std::abs(delta) > delta_bar)
    fail("", "hill_uncertainty_F: delta = " + number_text(delta) + ": must satisfy |delta| <= " +
         number_text(delta_bar));
  return hinf::models::hill::uncertainty_F(delta, delta_bar);
}

void validate_hill_model(const HillPlantSpec& model) {
  require_positive("orbital_rate", model.orbital_rate, "rad/s");
  require_positive("chaser_mass", model.chaser_mass, "kg");
  if (!std::isfinite(1.0 / model.chaser_mass))
    fail("chaser_mass", " = " + number_text(model.chaser_mass) +
                            ": too small, 1/chaser_mass (the thrust input matrix G₀, docs/maths.md §9.4) "
                            "is not finite");
  require_positive("sample_time", model.sample_time, "s");
  if (!std::isfinite(model.delta_bar) || model.delta_bar < 0 || model.delta_bar >= 10)
    fail("delta_bar", " = " + number_text(model.delta_bar) +
         ": must be in [0, 10) (relative uncertainty of the orbital rate)");

  if (model.K.size() > 0 && (model.K.rows() != 3 || model.K.cols() != 6))
    fail("K", ": expected 3x6 (3 thrust axes x 6 states), got " + dims(model.K));
  require_finite_entries(model.K, "K");

  if (model.B.rows() != 6 || model.B.cols() < 1)
    fail("B", ": expected 6 rows (the Hill state) and at least 1 column, got " + dims(model.B));
  require_finite_entries(model.B, "B");

  const MatrixXd C = measurement_matrix(model);
  if (C.cols() != 6 || C.rows() < 1)
    fail("C", ": expected 6 columns (the Hill state) and at least 1 row, got " + dims(C));
  require_finite_entries(C, "C");

  if (model.D.rows() != C.rows() || model.D.cols() < 1)
    fail("D", ": expected " + std::to_string(C.rows()) +
         " rows (m from C) and at least 1 column, got " + dims(model.D));
  require_finite_entries(model.D, "D");

  const MatrixXd L = estimated_signal_matrix(model);
  if (L.cols() != 6 || L.rows() < 1)
    fail("L", ": expected 6 columns (the Hill state) and at least 1 row, got " + dims(L));
  require_finite_entries(L, "L");
}

Plant build_hill_plant(const HillPlantSpec& model) {
  validate_hill_model(model);
  const hill::Discrete d = hill::discretise(closed_loop_A(model, model.orbital_rate),
                                            hill::input_matrix(model.chaser_mass), model.sample_time,
                                            model.discretisation);
  Plant plant;
  plant.A = d.A;
  plant.B = model.B;
  plant.C = measurement_matrix(model);
  plant.D = model.D;
  plant.L = estimated_signal_matrix(model);
  if (model.delta_bar > 0) {
    plant.H = d.Gamma * hill::uncertainty_H_a(model.orbital_rate);             // H = Γ·H_a
    plant.E = hill::uncertainty_E_a(model.orbital_rate, model.delta_bar);     // E = E_a
  } else {
    plant.H = MatrixXd::Zero(6, 0);
    plant.E = MatrixXd::Zero(0, 6);
  }
  require_representable(model, plant);
  validate_plant(plant);
  plant.G = MatrixXd::Zero(6, 0);  // no known input (the thrust is in A through K, or absent)
  return plant;
}

MatrixXd hill_exact_discrete_A(const HillPlantSpec& model, double delta) {
  validate_hill_model(model);
  if (!std::isfinite(delta))
    fail("", "hill_exact_discrete_A: delta = " + number_text(delta) + ": must be finite");
  const hill::Matrix6 Ac = closed_loop_A(model, model.orbital_rate * (1 + delta));
  return hill::discretise(Ac, hill::input_matrix(model.chaser_mass), model.sample_time, model.discretisation).A;
}

}  // namespace hinf::synth
