#include "hinf/lmi/lmi_problem.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hinf::lmi {

LmiProblem::LmiProblem(std::vector<int> block_sizes) : block_sizes_(std::move(block_sizes)) {
  for (int s : block_sizes_) {
    if (s < 0) throw std::invalid_argument("LmiProblem: negative block size");
    block_offsets_.push_back(order_);
    order_ += s;
  }
  M0_ = Eigen::MatrixXd::Zero(order_, order_);
}

VarId LmiProblem::add_symmetric(const std::string& name, int n) {
  Variable v{name, VarShape::Symmetric, n, n, num_params_, n * (n + 1) / 2, raw_size_, n * n};
  // raw (i,j) (column-major) → parameter of the upper-triangular entry (min, max),
  // parameters numbered column by column over the upper triangle.
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int r = std::min(i, j), c = std::max(i, j);
      raw_to_param_.push_back(num_params_ + c * (c + 1) / 2 + r);
    }
  variables_.push_back(v);
  num_params_ += v.num_params;
  raw_size_ += v.raw_size;
  return VarId{static_cast<int>(variables_.size()) - 1};
}

VarId LmiProblem::add_full(const std::string& name, int rows, int cols) {
  Variable v{name, VarShape::Full, rows, cols, num_params_, rows * cols, raw_size_, rows * cols};
  for (int k = 0; k < rows * cols; ++k) raw_to_param_.push_back(num_params_ + k);
  variables_.push_back(v);
  num_params_ += v.num_params;
  raw_size_ += v.raw_size;
  return VarId{static_cast<int>(variables_.size()) - 1};
}

VarId LmiProblem::add_scalar(const std::string& name) {
  Variable v{name, VarShape::Scalar, 1, 1, num_params_, 1, raw_size_, 1};
  raw_to_param_.push_back(num_params_);
  variables_.push_back(v);
  num_params_ += 1;
  raw_size_ += 1;
  return VarId{static_cast<int>(variables_.size()) - 1};
}

void LmiProblem::check_block(int r, int c, int rows, int cols, const char* what) const {
  if (r < 0 || c < 0 || r >= num_blocks() || c >= num_blocks() || r > c)
    throw std::invalid_argument(std::string("LmiProblem: ") + what + ": bad block (" +
                                std::to_string(r) + "," + std::to_string(c) + ")");
  if (rows != block_sizes_[r] || cols != block_sizes_[c])
    throw std::invalid_argument(std::string("LmiProblem: ") + what + " at block (" +
                                std::to_string(r) + "," + std::to_string(c) + ") is " +
                                std::to_string(rows) + "x" + std::to_string(cols) +
                                ", block is " + std::to_string(block_sizes_[r]) + "x" +
                                std::to_string(block_sizes_[c]));
}

static bool is_scaled_identity(const Eigen::MatrixXd& M, double& alpha) {
  if (M.rows() != M.cols() || M.rows() == 0) return false;
  alpha = M(0, 0);
  return (M - alpha * Eigen::MatrixXd::Identity(M.rows(), M.cols())).cwiseAbs().maxCoeff() == 0.0;
}

void LmiProblem::push_term(int var, int r, int c, double w, const Eigen::MatrixXd& L,
                           const Eigen::MatrixXd& R) {
  Term t;
  t.var = var;
  t.r = r;
  t.c = c;
  t.w = w;
  t.L.M = L;
  t.L.scaled_identity = is_scaled_identity(L, t.L.alpha);
  t.R.M = R;
  t.R.scaled_identity = is_scaled_identity(R, t.R.alpha);
  t.a = static_cast<int>(L.cols());
  t.b = static_cast<int>(R.rows());
  terms_.push_back(std::move(t));
}

void LmiProblem::add_term(int r, int c, VarId X, const Eigen::MatrixXd& left,
                          const Eigen::MatrixXd& right, bool transpose, bool symmetrize) {
  const Variable& v = variables_.at(X.index);
  if (v.shape == VarShape::Scalar)
    throw std::invalid_argument("LmiProblem: use add_scalar_term for scalar " + v.name);
  const int a = transpose ? v.cols : v.rows, b = transpose ? v.rows : v.cols;
  if (left.cols() != a || right.rows() != b)
    throw std::invalid_argument("LmiProblem: term in " + v.name + " has inner dimensions " +
                                std::to_string(left.cols()) + "," + std::to_string(right.rows()) +
                                ", variable is " + std::to_string(a) + "x" + std::to_string(b));
  check_block(r, c, static_cast<int>(left.rows()), static_cast<int>(right.cols()), v.name.c_str());
  const double w = (r != c || symmetrize) ? 1.0 : 0.5;
  // L·Xᵀ·R at (r, c) is the transpose of Rᵀ·X·Lᵀ at (c, r): store it that way.
  if (transpose) push_term(X.index, c, r, w, right.transpose(), left.transpose());
  else push_term(X.index, r, c, w, left, right);
}

void LmiProblem::add_scalar_term(int r, int c, VarId x, const Eigen::MatrixXd& K) {
  const Variable& v = variables_.at(x.index);
  if (v.shape != VarShape::Scalar)
    throw std::invalid_argument("LmiProblem: add_scalar_term needs a scalar, got " + v.name);
  check_block(r, c, static_cast<int>(K.rows()), static_cast<int>(K.cols()), v.name.c_str());
  const int s = static_cast<int>(K.cols());
  push_term(x.index, r, c, r != c ? 1.0 : 0.5, K, Eigen::MatrixXd::Identity(s, s));
}

void LmiProblem::add_constant(int r, int c, const Eigen::MatrixXd& K) {
  check_block(r, c, static_cast<int>(K.rows()), static_cast<int>(K.cols()), "constant");
  M0_.block(block_offsets_[r], block_offsets_[c], K.rows(), K.cols()) += K;
  if (r != c) M0_.block(block_offsets_[c], block_offsets_[r], K.cols(), K.rows()) += K.transpose();
}

Eigen::VectorXd LmiProblem::cost_of(VarId id) const {
  const Variable& v = variables_.at(id.index);
  if (v.shape != VarShape::Scalar)
    throw std::invalid_argument("LmiProblem::cost_of: " + v.name + " is not a scalar variable");
  Eigen::VectorXd c = Eigen::VectorXd::Zero(num_params_);
  c(v.offset) = 1.0;
  return c;
}

Eigen::MatrixXd LmiProblem::value(VarId id, const Eigen::VectorXd& x) const {
  const Variable& v = variables_.at(id.index);
  Eigen::MatrixXd X(v.rows, v.cols);
  for (int j = 0; j < v.cols; ++j)
    for (int i = 0; i < v.rows; ++i) X(i, j) = x(raw_to_param_[v.raw_offset + i + v.rows * j]);
  return X;
}

void LmiProblem::set_value(VarId id, const Eigen::MatrixXd& X, Eigen::VectorXd& x) const {
  const Variable& v = variables_.at(id.index);
  if (X.rows() != v.rows || X.cols() != v.cols)
    throw std::invalid_argument("LmiProblem::set_value: wrong shape for " + v.name);
  for (int j = 0; j < v.cols; ++j)
    for (int i = 0; i < v.rows; ++i) {
      if (v.shape == VarShape::Symmetric && i > j) continue;  // upper triangle defines it
      x(raw_to_param_[v.raw_offset + i + v.rows * j]) = X(i, j);
    }
}

Eigen::MatrixXd LmiProblem::evaluate(const Eigen::VectorXd& x) const {
  Eigen::MatrixXd M = M0_;
  for (const Term& t : terms_) {
    const Variable& v = variables_[t.var];
    const Eigen::MatrixXd G = v.shape == VarShape::Scalar
                                  ? Eigen::MatrixXd(x(v.offset) * Eigen::MatrixXd::Identity(t.a, t.b))
                                  : value(VarId{t.var}, x);
    const Eigen::MatrixXd T = t.w * (t.L.M * G * t.R.M);
    M.block(block_offsets_[t.r], block_offsets_[t.c], T.rows(), T.cols()) += T;
    M.block(block_offsets_[t.c], block_offsets_[t.r], T.cols(), T.rows()) += T.transpose();
  }
  return M;
}

void LmiProblem::product(const Factor& left, bool tl, const Eigen::Ref<const Eigen::MatrixXd>& Y,
                         const Factor& right, bool tr, Eigen::MatrixXd& out) {
  if (left.scaled_identity && right.scaled_identity) {
    out = (left.alpha * right.alpha) * Y;
  } else if (left.scaled_identity) {
    if (tr) out.noalias() = left.alpha * Y * right.M.transpose();
    else out.noalias() = left.alpha * Y * right.M;
  } else if (right.scaled_identity) {
    if (tl) out.noalias() = right.alpha * left.M.transpose() * Y;
    else out.noalias() = right.alpha * left.M * Y;
  } else {
    Eigen::MatrixXd tmp;
    if (tl) tmp.noalias() = left.M.transpose() * Y;
    else tmp.noalias() = left.M * Y;
    if (tr) out.noalias() = tmp * right.M.transpose();
    else out.noalias() = tmp * right.M;
  }
}

void LmiProblem::trace_products(const Eigen::MatrixXd& Y, Eigen::VectorXd& g) const {
  // tr(Y·w(T + Tᵀ)) = 2w·tr(Y[c, r] L G R) = 2w·tr(G Z),  Z = R Y[c, r] L;  ∂/∂G(i,j) = Z(j, i).
  Eigen::VectorXd graw = Eigen::VectorXd::Zero(raw_size_);
  Eigen::MatrixXd Z;
  for (const Term& t : terms_) {
    const Variable& v = variables_[t.var];
    product(t.R, false, wblock(Y, t.c, t.r), t.L, false, Z);
    if (v.shape == VarShape::Scalar) {
      graw(v.raw_offset) += 2 * t.w * Z.trace();
      continue;
    }
    for (int j = 0; j < t.b; ++j)
      for (int i = 0; i < t.a; ++i) graw(v.raw_offset + i + t.a * j) += 2 * t.w * Z(j, i);
  }
  g = Eigen::VectorXd::Zero(num_params_);
  for (int r = 0; r < raw_size_; ++r) g(raw_to_param_[r]) += graw(r);
}

bool LmiProblem::hessian(const Eigen::MatrixXd& W, Eigen::MatrixXd& Hs,
                         const std::function<bool()>& interrupted) const {
  // For terms h = (L, X, R) at (r, c) and k = (L', Y, R') at (r', c'), with W symmetric:
  //   tr(W dM_h W dM_k) = 2 w w' [ tr(X Q₁ Y P₁) + tr(X Q₂ Yᵀ P₂) ]
  //   Q₁ = R W[c, r'] L',  P₁ = R' W[c', r] L,  Q₂ = R W[c, c'] R'ᵀ,  P₂ = L'ᵀ W[r', r] L.
  // With X = e_i e_jᵀ, Y = e_k e_lᵀ:  Q₁(j,k)·P₁(l,i) + Q₂(j,l)·P₂(k,i).
  // Only pairs h ≤ k are computed; the k > h block is mirrored.
  Hraw_.setZero(raw_size_, raw_size_);
  Eigen::MatrixXd Q1, P1, Q2, P2, tmp;
  const int nt = static_cast<int>(terms_.size());
  for (int ih = 0; ih < nt; ++ih) {
    if (interrupted && interrupted()) return false;
    const Term& h = terms_[ih];
    const Variable& vh = variables_[h.var];
    const bool hs = vh.shape == VarShape::Scalar;
    for (int ik = ih; ik < nt; ++ik) {
      const Term& k = terms_[ik];
      const Variable& vk = variables_[k.var];
      const bool ks = vk.shape == VarShape::Scalar;
      // pairs h < k are mirrored at the end; h == k is counted half, then mirrored
      const double f = (ik == ih ? 1.0 : 2.0) * h.w * k.w;
      product(h.R, false, wblock(W, h.c, k.r), k.L, false, Q1);
      product(k.R, false, wblock(W, k.c, h.r), h.L, false, P1);
      product(h.R, false, wblock(W, h.c, k.c), k.R, true, Q2);
      product(k.L, true, wblock(W, k.r, h.r), h.L, false, P2);
      const int oh = vh.raw_offset, ok = vk.raw_offset;
      if (hs && ks) {
        const double v = f * ((Q1 * P1).trace() + (Q2 * P2).trace());
        Hraw_(oh, ok) += v;
        continue;
      }
      if (hs) {
        // X = I: Σ_i Q₁(i,k)P₁(l,i) = (P₁Q₁)(l,k);  Σ_i Q₂(i,l)P₂(k,i) = (P₂Q₂)(k,l)
        tmp.noalias() = (P1 * Q1).transpose();
        tmp.noalias() += P2 * Q2;  // tmp(k, l)
        for (int l = 0; l < k.b; ++l)
          for (int kk = 0; kk < k.a; ++kk) {
            const double v = f * tmp(kk, l);
            Hraw_(oh, ok + kk + k.a * l) += v;
          }
        continue;
      }
      if (ks) {
        // Y = I: Σ_k Q₁(j,k)P₁(k,i) = (Q₁P₁)(j,i);  Σ_k Q₂(j,k)P₂(k,i) = (Q₂P₂)(j,i)
        tmp.noalias() = Q1 * P1;
        tmp.noalias() += Q2 * P2;  // tmp(j, i)
        for (int j = 0; j < h.b; ++j)
          for (int i = 0; i < h.a; ++i) {
            const double v = f * tmp(j, i);
            Hraw_(oh + i + h.a * j, ok) += v;
          }
        continue;
      }
      // block (j, l): rows i (a of h), cols kk (a of k):
      //   f·P₁(l, i)·Q₁(j, kk)  +  f·Q₂(j, l)·P₂(kk, i)
      // one pass over each column of the block (contiguous in i), with the two factors
      // that run over i transposed once so that they are contiguous too
      fP1t_.noalias() = f * P1.transpose();  // (a × b'): fP1t(i, l) = f·P₁(l, i)
      P2t_.noalias() = P2.transpose();       // (a × a'): P2t(i, kk) = P₂(kk, i)
      for (int j = 0; j < h.b; ++j)
        for (int l = 0; l < k.b; ++l) {
          const double fq2 = f * Q2(j, l);
          const double* p1 = fP1t_.col(l).data();
          for (int kk = 0; kk < k.a; ++kk) {
            const double q1 = Q1(j, kk);
            const double* p2 = P2t_.col(kk).data();
            double* hc = &Hraw_(oh + h.a * j, ok + kk + k.a * l);
            for (int i = 0; i < h.a; ++i) {
              double v = hc[i];
              v += p1[i] * q1;
              v += fq2 * p2[i];
              hc[i] = v;
            }
          }
        }
    }
  }
  Hsym_ = Hraw_ + Hraw_.transpose();
  contract_raw(Hsym_, Hs);
  return true;
}

double LmiProblem::product_multiply_adds(const Factor& left, const Factor& right, double m, double s1, double s2,
                                         double n) {
  if (left.scaled_identity && right.scaled_identity) return m * s2;  // a scaled copy
  return (left.scaled_identity ? 0.0 : m * s1 * s2) + (right.scaled_identity ? 0.0 : m * s2 * n);
}

double LmiProblem::hessian_multiply_adds() const {
  // The same pairs and products as hessian(), each counted by its shapes.
  double work = 0;
  const int nt = static_cast<int>(terms_.size());
  for (int ih = 0; ih < nt; ++ih) {
    const Term& h = terms_[ih];
    const double sr = block_sizes_[h.r], sc = block_sizes_[h.c];
    for (int ik = ih; ik < nt; ++ik) {
      const Term& k = terms_[ik];
      const double kr = block_sizes_[k.r], kc = block_sizes_[k.c];
      work += product_multiply_adds(h.R, k.L, h.b, sc, kr, k.a);  // Q₁
      work += product_multiply_adds(k.R, h.L, k.b, kc, sr, h.a);  // P₁
      work += product_multiply_adds(h.R, k.R, h.b, sc, kc, k.b);  // Q₂
      work += product_multiply_adds(k.L, h.L, k.a, kr, sr, h.a);  // P₂
      work += 2.0 * h.a * h.b * k.a * k.b;                        // the block's update (fewer for scalars)
    }
  }
  const double raw = raw_size_;
  return work + 3.0 * raw * raw;  // Hraw + Hrawᵀ and the two passes of contract_raw
}

void LmiProblem::scaled_jacobian(const Eigen::MatrixXd& T, Eigen::MatrixXd& G, int first_row) const {
  const int N = order_, f = first_row;
  const double s2 = std::sqrt(2.0);
  G.topRows(scaled_jacobian_rows(N, f)).setZero();
  Eigen::MatrixXd U, V;
  for (const Term& t : terms_) {
    const Variable& v = variables_[t.var];
    // U = T[:, block r]·left (N×a),  V = T[:, block c]·rightᵀ (N×b)
    U.noalias() = T.middleCols(block_offsets_[t.r], block_sizes_[t.r]) * t.L.M;
    V.noalias() = T.middleCols(block_offsets_[t.c], block_sizes_[t.c]) * t.R.M.transpose();
    // Pairs (i, j) of the term's G entry and the parameter they move: a full/symmetric
    // variable's entry (i, j); a scalar x·I_s moves all (k, k) together.
    const bool scalar = v.shape == VarShape::Scalar;
    const int npairs = scalar ? t.a : t.a * t.b;
    for (int q = 0; q < npairs; ++q) {
      const int i = scalar ? q : q % t.a, j = scalar ? q : q / t.a;
      const int param = scalar ? v.offset : raw_to_param_[v.raw_offset + i + t.a * j];
      const auto u = U.col(i);
      const auto w = V.col(j);
      double* g = G.col(param).data();
      int k = 0;
      for (int c = 0; c < N; ++c) {
        if (c >= f) g[k++] += 2 * t.w * u(c) * w(c);
        const double uc = s2 * t.w * u(c), wc = s2 * t.w * w(c);
        for (int r = std::max(c + 1, f); r < N; ++r) g[k++] += uc * w(r) + wc * u(r);
      }
    }
  }
}

void LmiProblem::contract_raw(const Eigen::MatrixXd& Hraw, Eigen::MatrixXd& Hs) const {
  Hrows_.setZero(num_params_, raw_size_);
  for (int r = 0; r < raw_size_; ++r) Hrows_.row(raw_to_param_[r]) += Hraw.row(r);
  Hs.setZero(num_params_, num_params_);
  for (int r = 0; r < raw_size_; ++r) Hs.col(raw_to_param_[r]) += Hrows_.col(r);
}

Eigen::MatrixXd LmiProblem::basis_matrix(int param) const {
  Eigen::VectorXd e = Eigen::VectorXd::Zero(num_params_);
  e(param) = 1.0;
  return evaluate(e) - M0_;
}

std::vector<SparseEntry> LmiProblem::sparse_entries() const {
  std::vector<SparseEntry> out;
  for (int i = 0; i < num_params_; ++i) {
    const Eigen::MatrixXd Mi = basis_matrix(i);
    for (int c = 0; c < order_; ++c)
      for (int r = 0; r <= c; ++r)
        if (Mi(r, c) != 0.0) out.push_back({i, r, c, Mi(r, c)});
  }
  return out;
}

}  // namespace hinf::lmi
