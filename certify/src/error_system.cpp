// Error system docs/maths.md (9)–(11); see error_system.hpp.
#include "hinf/certify/error_system.hpp"

#include <algorithm>
#include <cmath>
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

// The observer-form error system (122)–(123): e = x − x̂ with x̂(k+1) = A x̂ + G u + K(y − C x̂),
//     e(k+1) = (A + ΔA − K C) e + B w − K D v,   z − ẑ = L e                (predictor)
//     z − ẑ(k|k) = (L − N C) e − N D v,  N = L M                            (filtered, (141))
// from the plant and the gains K (and M) alone (the realisation A_F, B_F, C_F, D_F, G_F is
// checked against it by observer_form_mismatch).
StateSpace observer_error_system(const Plant& plant, const Filter& filter, const Eigen::MatrixXd& A_delta) {
  const Eigen::Index n = plant.A.rows(), p = plant.B.cols(), m = plant.C.rows(), q = plant.D.cols();
  require(filter.K.rows() == n && filter.K.cols() == m,
          "observer gain K is " + dims(filter.K) + ", expected " + std::to_string(n) + "×" + std::to_string(m));
  StateSpace s;
  s.A = A_delta - filter.K * plant.C;
  s.B.resize(n, p + q);
  s.B << plant.B, -filter.K * plant.D;
  s.D = Eigen::MatrixXd::Zero(plant.L.rows(), p + q);
  if (!filter.filtered()) {
    s.C = plant.L;
    return s;
  }
  require(filter.M.rows() == n && filter.M.cols() == m,
          "filtered-observer gain M is " + dims(filter.M) + ", expected " + std::to_string(n) + "×" +
              std::to_string(m));
  const Eigen::MatrixXd N = plant.L * filter.M;
  s.C = plant.L - N * plant.C;
  s.D.rightCols(q) = -N * plant.D;
  return s;
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
  if (filter.form == FilterForm::Observer) return observer_error_system(plant, filter, A_delta);
  require(filter.D_F.size() == 0 && filter.M.size() == 0,
          "only an observer-form filter has a filtered variant (M, D_F)");

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

double observer_form_mismatch(const Plant& plant, const Filter& filter) {
  const Eigen::Index n = plant.A.rows(), m = plant.C.rows(), l = plant.L.rows();
  if (filter.K.rows() != n || filter.K.cols() != m || filter.A_F.rows() != n || filter.A_F.cols() != n ||
      filter.B_F.rows() != n || filter.B_F.cols() != m || filter.C_F.rows() != l || filter.C_F.cols() != n)
    return INFINITY;
  const Eigen::MatrixXd G = plant.G.size() > 0 ? plant.G : Eigen::MatrixXd::Zero(n, 0);
  const Eigen::MatrixXd GF = filter.G_F.size() > 0 ? filter.G_F : Eigen::MatrixXd::Zero(n, 0);
  if (G.cols() != GF.cols() || GF.rows() != n) return INFINITY;
  // each entry against the size of the products that form it
  const Eigen::MatrixXd scale_A = plant.A.cwiseAbs() + filter.K.cwiseAbs() * plant.C.cwiseAbs();
  auto worst = [](const Eigen::MatrixXd& diff, const Eigen::MatrixXd& scale) {
    double w = 0;
    for (Eigen::Index i = 0; i < diff.size(); ++i)
      w = std::max(w, std::abs(diff(i)) / std::max(scale(i), 1e-300));
    return w;
  };
  double mismatch = std::max({worst(filter.A_F - (plant.A - filter.K * plant.C), scale_A),
                              worst(filter.B_F - filter.K, filter.K.cwiseAbs()), worst(GF - G, G.cwiseAbs())});
  if (!filter.filtered()) {
    if (filter.D_F.size() > 0) return INFINITY;
    return std::max(mismatch, worst(filter.C_F - plant.L, plant.L.cwiseAbs()));
  }
  // filtered variant (140): C_F = L − L M C, D_F = L M
  if (filter.M.rows() != n || filter.M.cols() != m || filter.D_F.rows() != l || filter.D_F.cols() != m)
    return INFINITY;
  const Eigen::MatrixXd N = plant.L * filter.M, scale_N = plant.L.cwiseAbs() * filter.M.cwiseAbs();
  return std::max({mismatch, worst(filter.D_F - N, scale_N),
                   worst(filter.C_F - (plant.L - N * plant.C), plant.L.cwiseAbs() + scale_N * plant.C.cwiseAbs())});
}

}  // namespace hinf::certify
