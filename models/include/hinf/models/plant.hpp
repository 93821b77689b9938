// The uncertain discrete-time plant of docs/maths.md (1)–(4), with the known input of (120):
//   x(k+1) = (A + H F(k) E) x(k) + G u(k) + B w(k),  y(k) = C x(k) + D v(k),  z(k) = L x(k),
//   F(k)ᵀF(k) ≤ I (F block-diagonal when F_blocks says so).
#pragma once
#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

namespace hinf {

struct Plant {
  Eigen::MatrixXd A;  // n×n
  Eigen::MatrixXd B;  // n×p
  Eigen::MatrixXd C;  // m×n
  Eigen::MatrixXd D;  // m×q
  Eigen::MatrixXd L;  // l×n
  Eigen::MatrixXd H;  // n×j  (0 columns: no uncertainty)
  Eigen::MatrixXd E;  // k×n  (0 rows: no uncertainty)
  Eigen::MatrixXd G;  // n×r  known input u, which the filter receives too (0 columns: none)
  // The sizes of F's square diagonal blocks, F = diag(F₁, …, F_K), each ‖F_b‖ ≤ 1, summing
  // to j = k (docs/maths.md §23); empty: F is one full j×k block (4).
  std::vector<int> F_blocks;

  int n() const { return static_cast<int>(A.rows()); }
  int p() const { return static_cast<int>(B.cols()); }
  int m() const { return static_cast<int>(C.rows()); }
  int q() const { return static_cast<int>(D.cols()); }
  int l() const { return static_cast<int>(L.rows()); }
  int j() const { return static_cast<int>(H.cols()); }
  int k() const { return static_cast<int>(E.rows()); }
  int r() const { return static_cast<int>(G.cols()); }
  bool uncertain() const { return H.size() > 0 && E.size() > 0; }
  // F has more than one diagonal block: one S-procedure multiplier per block (§23).
  bool structured() const { return uncertain() && F_blocks.size() > 1; }
  // The (first column of H / row of E, size) of each block of F; one block j×k if not structured.
  std::vector<std::pair<int, int>> F_block_ranges() const {
    std::vector<std::pair<int, int>> out;
    if (!structured()) return {{0, j()}};
    int at = 0;
    for (int b : F_blocks) out.emplace_back(at, b), at += b;
    return out;
  }
};

// The two formulations of the full-order filter (docs/maths.md §2.2 and §18):
//   Augmented  any (A_F, B_F, C_F); its error system (10) contains the plant state, so the
//              plant must be robustly Schur stable (Theorem 1, §3);
//   Observer   A_F = A − K C, B_F = K, C_F = L, G_F = G: the estimate x̂ of x itself, whose
//              error e = x − x̂ obeys (122) and needs (A, C) detectable only.
// An observer-form filter estimates z(k) from y(0..k−1) (the predictor) or, in its filtered
// variant (docs/maths.md §18.6), from y(0..k): ẑ(k|k) = L x̂(k|k), x̂(k|k) = x̂ + M(y − C x̂),
// so C_F = L − L M C and the output has the feedthrough D_F = L M.
enum class FilterForm { Augmented, Observer };

inline const char* to_string(FilterForm f) { return f == FilterForm::Observer ? "observer" : "augmented"; }

// Which estimate of z(k) an observer-form filter gives: from y(0..k−1) (the one-step
// predictor, (122)) or from y(0..k) (the filtered variant, docs/maths.md §18.6).
enum class Estimate { Predicted, Filtered };

inline const char* to_string(Estimate e) { return e == Estimate::Filtered ? "filtered" : "predicted"; }

// The fixed-gain full-order filter of docs/maths.md (5)–(6), with the known input (121) and,
// for the filtered observer (140), the feedthrough D_F:
//   x_F(k+1) = A_F x_F(k) + B_F y(k) + G_F u(k),  z_F(k) = C_F x_F(k) + D_F y(k).
struct Filter {
  Filter() = default;
  // An augmented-form filter without a known input.
  Filter(Eigen::MatrixXd a_f, Eigen::MatrixXd b_f, Eigen::MatrixXd c_f)
      : A_F(std::move(a_f)), B_F(std::move(b_f)), C_F(std::move(c_f)) {}

  Eigen::MatrixXd A_F;  // n×n
  Eigen::MatrixXd B_F;  // n×m
  Eigen::MatrixXd C_F;  // l×n
  FilterForm form = FilterForm::Augmented;
  Eigen::MatrixXd K;    // n×m observer gain (observer form only; equals B_F)
  Eigen::MatrixXd G_F;  // n×r known-input matrix (empty or n×0 without a known input)
  // Filtered observer only (docs/maths.md (140)); both empty for a predictor:
  Eigen::MatrixXd M;    // n×m: x̂(k|k) = x̂(k) + M (y(k) − C x̂(k))
  Eigen::MatrixXd D_F;  // l×m feedthrough, equals L M

  // The filtered variant of the observer form: z_F(k) uses y(k).
  bool filtered() const { return M.size() > 0; }
};

}  // namespace hinf
