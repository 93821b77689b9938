// Error system docs/maths.md (9)–(11); see error_system.hpp.
#include "hinf/certify/error_system.hpp"

#include <sstream>
#include <string>

#include "hinf/common/error.hpp"

namespace hinf::certify {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw Error(ErrorCode::InvalidInput, "error_system: " + what);
}

std::string dims(const Eigen::MatrixXd& M) {
  return std::to_string(M.rows()) + "×" + std::to_string(M.cols());
}

}  // namespace

StateSpace error_system(const Plant& plant, const Filter& filter, const Eigen::MatrixXd& F) {
  const Eigen::Index n = plant.A.rows(), p = plant.B.cols(), m = plant.C.rows(),
                     q = plant.D.cols(), l = plant.L.rows();
  require(plant.A.cols() == n && plant.B.rows() == n && plant.C.cols() == n &&
              plant.D.rows() == m && plant.L.cols() == n,
          "inconsistent plant dimensions (A " + dims(plant.A) + ", B " + dims(plant.B) +
              ", C " + dims(plant.C) + ", D " + dims(plant.D) + ", L " + dims(plant.L) + ")");
  const Eigen::Index nf = filter.A_F.rows();
  require(filter.A_F.cols() == nf && filter.B_F.rows() == nf && filter.B_F.cols() == m &&
              filter.C_F.rows() == l && filter.C_F.cols() == nf,
          "filter dimensions (A_F " + dims(filter.A_F) + ", B_F " + dims(filter.B_F) +
              ", C_F " + dims(filter.C_F) + ") do not match the plant (m = " +
              std::to_string(m) + ", l = " + std::to_string(l) + ")");

  Eigen::MatrixXd A_delta = plant.A;
  if (F.size() > 0) {
    require(plant.H.rows() == n && plant.E.cols() == n, "H must be n×j and E k×n");
    require(F.rows() == plant.H.cols() && F.cols() == plant.E.rows(),
            "F is " + dims(F) + ", expected " + std::to_string(plant.H.cols()) + "×" +
                std::to_string(plant.E.rows()));
    A_delta += plant.H * F * plant.E;  // A + ΔA, ΔA = H F E
  }

  StateSpace s;
  s.A = Eigen::MatrixXd::Zero(n + nf, n + nf);  // Ā = [A+ΔA, 0; B_F C, A_F]
  s.A.topLeftCorner(n, n) = A_delta;
  s.A.bottomLeftCorner(nf, n) = filter.B_F * plant.C;
  s.A.bottomRightCorner(nf, nf) = filter.A_F;
  s.B = Eigen::MatrixXd::Zero(n + nf, p + q);   // B̄ = [B, 0; 0, B_F D]
  s.B.topLeftCorner(n, p) = plant.B;
  s.B.bottomRightCorner(nf, q) = filter.B_F * plant.D;
  s.C.resize(l, n + nf);                         // C̄ = [L, −C_F]
  s.C << plant.L, -filter.C_F;
  s.D = Eigen::MatrixXd::Zero(l, p + q);
  return s;
}

}  // namespace hinf::certify
