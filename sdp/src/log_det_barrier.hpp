// The log-barrier objective of the path-following method (docs/maths.md (28)–(29), (38)):
//   phase II:  f_t(x)    = t·cᵀx − log det(−M(x) − εI)          − log(ρ² − ‖x‖²)
//   phase I:   f_t(x, s) = t·s   − log det(−M(x) − εI + s·I)    − log(ρ² − ‖x‖²)
// ε is the strictness margin (docs/maths.md (26), [D2], [D3]), ρ the feasibility radius
// (as LMI Lab's feasradius; §4.3) that keeps the barrier bounded below. Knows nothing of Ipopt.
#pragma once
#include <Eigen/Dense>
#include <chrono>
#include <functional>

#include "hinf/lmi/lmi_problem.hpp"

namespace hinf::sdp {

class LogDetBarrier {
 public:
  // phase1_weight η: phase I minimises s + η·cᵀx (η > 0 keeps the phase-I centre from
  // drifting to huge objective values, which phase II would then have to undo).
  LogDetBarrier(const lmi::LmiProblem& lmi, Eigen::VectorXd c, double margin, double radius,
                bool phase1, double phase1_weight = 0.0);

  int dim() const { return n_ + (phase1_ ? 1 : 0); }
  bool phase1() const { return phase1_; }
  void set_t(double t) { t_ = t; }
  double t() const { return t_; }
  // After this instant, or once `interrupted` returns true, every Hessian assembly stops
  // early and the functions that need one return false (a large LMI's Hessian takes
  // seconds: the solver's time limit is kept within one term's work, not one Newton
  // iteration's).
  void set_deadline(std::chrono::steady_clock::time_point deadline, std::function<bool()> interrupted = nullptr) {
    deadline_ = deadline;
    interrupted_ = std::move(interrupted);
  }
  bool past_deadline() const {
    return std::chrono::steady_clock::now() > deadline_ || (interrupted_ && interrupted_());
  }
  // Called once per LMI term of every Hessian assembly (progress of a long one), if set.
  void set_heartbeat(std::function<void()> heartbeat) { heartbeat_ = std::move(heartbeat); }
  // The Hessian assembly's per-term check: the heartbeat, then the deadline.
  bool beat_and_check_deadline() const {
    if (heartbeat_) heartbeat_();
    return past_deadline();
  }

  // Each returns false when z is outside the barrier's domain (the Cholesky factor
  // of the slack fails or ‖x‖ ≥ ρ); Ipopt then shortens its step.
  bool value(const Eigen::VectorXd& z, double& f);
  bool gradient(const Eigen::VectorXd& z, Eigen::VectorXd& g);
  bool hessian(const Eigen::VectorXd& z, Eigen::MatrixXd& H);
  // Newton decrement squared λ² = gᵀH⁻¹g at z (the centring criterion).
  bool newton_decrement2(const Eigen::VectorXd& z, double& lambda2);
  // Central-path tangent dz/dt = −H⁻¹∇(linear objective) at z.
  bool path_tangent(const Eigen::VectorXd& z, Eigen::VectorXd& dz);

  // The same Newton step, decrement and tangent without forming H (phase II only).
  // H = GᵀG with G = [rows of the scaled Jacobian (LmiProblem::scaled_jacobian) that touch
  // the slack's p smallest eigenvalues; the factor of the rest of H, ball included]; with
  // G = QR, H·dz = −∇f_t is RᵀR·dz = −∇f_t and λ² = ‖R⁻ᵀ∇f_t‖². The condition number of
  // R is that of G, ~t, where the explicit H's is ~t²: late on the path (t ≳ 1e8 on
  // random n = 10 plants) the explicit H's round-off, ε·‖H‖, exceeds its smallest
  // eigenvalues and Newton on it stalls; on R it still converges quadratically. Costs a
  // QR of a (p(N − p) + p(p + 1)/2 + n) × n matrix (factor_jacobian), so it is used only
  // where the explicit H fails.
  bool accurate_newton(const Eigen::VectorXd& z, Eigen::VectorXd& dz, double& lambda2);
  bool accurate_path_tangent(const Eigen::VectorXd& z, Eigen::VectorXd& dz);

  double linear_objective(const Eigen::VectorXd& z) const;
  // ∇ of the linear objective
  Eigen::VectorXd objective_gradient() const;
  bool inside(const Eigen::VectorXd& z) { return factor(z); }
  // W = (slack)⁻¹ at the point of the last derivatives() (tests: W is exactly symmetric).
  const Eigen::MatrixXd& W() const { return W_; }

 private:
  bool factor(const Eigen::VectorXd& z);
  bool derivatives(const Eigen::VectorXd& z);
  bool factor_hessian();  // ldlt_ of hess_ at the point of the last derivatives()
  bool factor_jacobian(const Eigen::VectorXd& z);  // G_ and its QR at z
  // H += the Hessian of the feasibility ball −log(ρ² − ‖x‖²) at x
  void add_ball_hessian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::MatrixXd> H) const;

  const lmi::LmiProblem& lmi_;
  Eigen::VectorXd c_;
  double margin_, radius_;
  bool phase1_;
  double eta_;
  int n_;
  int N_;
  double t_ = 1.0;
  std::chrono::steady_clock::time_point deadline_ = std::chrono::steady_clock::time_point::max();
  std::function<void()> heartbeat_;
  std::function<bool()> interrupted_;

  // cache keyed by z
  Eigen::VectorXd z_factored_, z_derivs_;
  bool have_factor_ = false, have_derivs_ = false, factor_ok_ = false;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::MatrixXd slack_, W_;
  double logdet_ = 0, ball_ = 0;
  Eigen::VectorXd grad_phi_;   // ∇ of the barrier part (no t·c term)
  Eigen::MatrixXd hess_;       // ∇² of the barrier part
  Eigen::MatrixXd Hs_;         // workspace
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;  // of hess_ (Newton decrement, path tangent); reused storage
  bool hess_factored_ = false;         // ldlt_ is of the current hess_
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig_;  // accurate_newton: of the slack
  Eigen::MatrixXd Tsc_, Wm_, Hmod_;            // Λ^{-1/2}Qᵀ (reordered), W_m, H_mod
  Eigen::MatrixXd G_;                          // [G_p; F], then its QR in place (R on top)
  Eigen::LDLT<Eigen::MatrixXd> mod_ldlt_;      // of H_mod
  Eigen::VectorXd z_qr_;                       // the point G_'s QR is of
  bool have_qr_ = false;
};

}  // namespace hinf::sdp
