// A small generic LMI layer: decision variables (symmetric, full, scalar), affine
// block terms  left · X · right  placed in a block-partitioned symmetric matrix
//   M(x) = M₀ + Σᵢ xᵢ Mᵢ,
// and the derivatives of the log-det barrier φ(x) = −log det(−M(x)) (docs/maths.md §5.2):
//   ∂φ/∂xᵢ = tr(W Mᵢ),   ∂²φ/∂xᵢ∂xⱼ = tr(W Mᵢ W Mⱼ),   W = (−M)⁻¹.
// The Mᵢ are never formed: each term is kept as its factors (left, X, right), so a
// Hessian block between two terms is a permuted Kronecker product of two small dense
// products  Q = Rₚ W[cₚ,r_q] L_q,  P = R_q W[c_q,rₚ] Lₚ  (tr(Gₚ Q G_q P) = Q[j,k]·P[l,i]),
// the structure LMI Lab (Gahinet–Nemirovski) exploits. Cost: products of block sizes,
// independent of the order N of M except through the blocks a term touches.
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace hinf::lmi {

enum class VarShape { Symmetric, Full, Scalar };

struct Variable {
  std::string name;
  VarShape shape;
  int rows = 0, cols = 0;  // scalar: 1×1
  int offset = 0;          // first parameter index in x
  int num_params = 0;      // n(n+1)/2, rows·cols or 1
  int raw_offset = 0;      // first index in the "raw" (entry-wise) coordinates
  int raw_size = 0;        // rows·cols (1 for a scalar)
};

struct VarId {
  int index = -1;
};

// One sparse entry of a constraint matrix Mᵢ (lower or upper triangle, both stored).
struct SparseEntry {
  int param, row, col;
  double value;
};

class LmiProblem {
 public:
  explicit LmiProblem(std::vector<int> block_sizes);

  VarId add_symmetric(const std::string& name, int n);
  VarId add_full(const std::string& name, int rows, int cols);
  VarId add_scalar(const std::string& name);

  // Adds T = left · X · right (or left · Xᵀ · right) at block (r, c), r ≤ c, and Tᵀ at
  // (c, r). On a diagonal block, T is added as it is (the caller guarantees it is
  // symmetric, e.g. −R) unless `symmetrize`, which adds T + Tᵀ.
  void add_term(int r, int c, VarId X, const Eigen::MatrixXd& left, const Eigen::MatrixXd& right,
                bool transpose = false, bool symmetrize = false);
  // Adds x · K at block (r, c) for a scalar variable x (and Kᵀ at (c, r)).
  void add_scalar_term(int r, int c, VarId x, const Eigen::MatrixXd& K);
  // Adds the constant K at block (r, c) (and Kᵀ at (c, r)).
  void add_constant(int r, int c, const Eigen::MatrixXd& K);

  int order() const { return order_; }
  int num_params() const { return num_params_; }
  int num_blocks() const { return static_cast<int>(block_sizes_.size()); }
  int block_size(int b) const { return block_sizes_[b]; }
  int block_offset(int b) const { return block_offsets_[b]; }
  const std::vector<Variable>& variables() const { return variables_; }
  const Variable& variable(VarId v) const { return variables_[v.index]; }

  // The cost vector c with cᵀx = the value of the scalar variable v (minimise v).
  Eigen::VectorXd cost_of(VarId v) const;

  // x ↔ matrix value of a variable.
  Eigen::MatrixXd value(VarId v, const Eigen::VectorXd& x) const;
  void set_value(VarId v, const Eigen::MatrixXd& X, Eigen::VectorXd& x) const;

  // M(x) (dense, symmetric).
  Eigen::MatrixXd evaluate(const Eigen::VectorXd& x) const;
  const Eigen::MatrixXd& constant() const { return M0_; }
  // g_i = tr(Y Mᵢ) for a symmetric Y (the barrier gradient when Y = W).
  void trace_products(const Eigen::MatrixXd& Y, Eigen::VectorXd& g) const;
  // Hs_ij = tr(W Mᵢ W Mⱼ) (full symmetric matrix; the barrier Hessian). `interrupted`, if
  // given, is asked once per term (a Hessian of a large LMI takes seconds); when it says
  // true the assembly stops and false is returned, Hs left unspecified.
  bool hessian(const Eigen::MatrixXd& W, Eigen::MatrixXd& Hs,
               const std::function<bool()>& interrupted = nullptr) const;
  // Multiply-adds of one hessian() call, counted from the terms' shapes (the products Q₁,
  // P₁, Q₂, P₂ of every pair of terms, the fused update of their block, the contraction to
  // the parameters): the work the solver's time model (sdp/time_model.hpp) is built on.
  double hessian_multiply_adds() const;
  // The scaled Jacobian of the barrier for any T with TᵀT = W (the inverse Cholesky factor
  // of the slack, or Λ^{-1/2}Qᵀ from its eigendecomposition): column i = svec(T Mᵢ Tᵀ),
  // svec the lower triangle column by column with off-diagonal entries ×√2, so that GᵀG
  // is the barrier Hessian tr(W Mᵢ W Mⱼ). With first_row = f > 0 only the entries (r, c),
  // r ≥ c, with r ≥ f are emitted (the pairs that touch rows f.. of T); they fill rows
  // [0, scaled_jacobian_rows(N, f)) of G (num_params() columns). Each term contributes
  // rank-2 updates w·(u vᵀ + v uᵀ), u = T·left·eᵢ, v = T·rightᵀ·eⱼ: the Mᵢ are never
  // formed, and every column is built from the same T, so a combination Σ dᵢ Mᵢ that
  // nearly vanishes on the slack's near-null space keeps that property in G·d (what the
  // QR Newton step of the barrier relies on).
  void scaled_jacobian(const Eigen::MatrixXd& T, Eigen::MatrixXd& G, int first_row = 0) const;
  static int scaled_jacobian_rows(int N, int first_row) {
    const int p = N - first_row;
    return first_row * p + p * (p + 1) / 2;
  }
  // All Mᵢ as sparse entries (upper triangle, row ≤ col), for export and tests.
  std::vector<SparseEntry> sparse_entries() const;
  // Mᵢ as a dense matrix (tests).
  Eigen::MatrixXd basis_matrix(int param) const;

 private:
  // A constant factor of a term; α·I is kept as the scalar α (most terms of Theorem 1),
  // so products with it cost nothing.
  struct Factor {
    Eigen::MatrixXd M;
    bool scaled_identity = false;
    double alpha = 0;
  };
  // A term T = L·G·R placed at block (r, c), contributing w·(T + Tᵀ) to M (embedded):
  // w = 1 off the diagonal or when symmetrised, w = ½ for a symmetric diagonal term.
  // G is the variable X (a×b) or x·I_s for a scalar (a = b = s).
  struct Term {
    int var;
    int r, c;
    double w;
    Factor L, R;
    int a, b;
  };
  void push_term(int var, int r, int c, double w, const Eigen::MatrixXd& L, const Eigen::MatrixXd& R);
  void check_block(int r, int c, int rows, int cols, const char* what) const;
  void contract_raw(const Eigen::MatrixXd& Hraw, Eigen::MatrixXd& Hs) const;
  // Multiply-adds of product(left, ·, Y, right, ·) for an m×s₁ op(left), s₁×s₂ Y and s₂×n op(right).
  static double product_multiply_adds(const Factor& left, const Factor& right, double m, double s1, double s2,
                                      double n);
  // out = op(left) · Y · op(right), op = transpose when the flag is set.
  static void product(const Factor& left, bool tl, const Eigen::Ref<const Eigen::MatrixXd>& Y,
                      const Factor& right, bool tr, Eigen::MatrixXd& out);
  Eigen::Ref<const Eigen::MatrixXd> wblock(const Eigen::MatrixXd& W, int r, int c) const {
    return W.block(block_offsets_[r], block_offsets_[c], block_sizes_[r], block_sizes_[c]);
  }

  std::vector<int> block_sizes_, block_offsets_;
  int order_ = 0;
  int num_params_ = 0;
  int raw_size_ = 0;
  std::vector<Variable> variables_;
  std::vector<Term> terms_;
  Eigen::MatrixXd M0_;
  // raw → parameter map (each raw index maps to exactly one parameter with weight 1).
  std::vector<int> raw_to_param_;
  mutable Eigen::MatrixXd Hraw_, Hsym_, Hrows_, fP1t_, P2t_;  // workspace (sized at the first call, then reused)
};

}  // namespace hinf::lmi
