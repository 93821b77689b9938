// certify_controller, robust_channel_norm (controller_certificate.hpp).
#include "hinf/certify/controller_certificate.hpp"

#include <cmath>
#include <string>

#include "hinf/certify/balance.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/common/error.hpp"

namespace hinf::certify {

namespace {

// Relative accuracy of the closed-loop norms.
constexpr double kClosedLoopNormTolerance = 1e-10;

HinfNorm closed_loop_norm(const hinf::StateSpace& sys, bool discrete) {
  return discrete ? discrete_hinf_norm(sys, kClosedLoopNormTolerance) : continuous_hinf_norm(sys, kClosedLoopNormTolerance);
}

}  // namespace

void require_controller_fits(const hinf::GeneralisedPlant& P, const hinf::Controller& K) {
  const Eigen::Index nk = K.A_K.rows();
  const std::string plant = " for this plant (ny = " + std::to_string(P.ny()) + " measurements, nu = " +
                            std::to_string(P.nu()) + " controls)";
  const auto need = [&plant](const char* name, const Eigen::MatrixXd& M, Eigen::Index r, Eigen::Index c) {
    if (M.rows() != r || M.cols() != c)
      throw Error(ErrorCode::InvalidInput, std::string("controller.") + name + ": expected " + std::to_string(r) + "x" +
                                               std::to_string(c) + plant + ", got " + std::to_string(M.rows()) + "x" +
                                               std::to_string(M.cols()), name);
  };
  need("A_K", K.A_K, nk, nk);
  need("B_K", K.B_K, nk, P.ny());
  need("C_K", K.C_K, P.nu(), nk);
  need("D_K", K.D_K, P.nu(), P.ny());
}

double robust_channel_norm(const hinf::GeneralisedPlant& P, const hinf::StateSpace& cl,
                           const hinf::UncertaintyChannel& channel) {
  const Eigen::Index n = P.n(), ncl = cl.A.rows();
  if (channel.H.rows() != n || channel.E.cols() != n)
    throw Error(ErrorCode::InvalidInput, "controller.robust: H must have " + std::to_string(n) + " rows and E " +
                                             std::to_string(n) + " columns (the plant's states), got H " +
                                             std::to_string(channel.H.rows()) + "x" + std::to_string(channel.H.cols()) +
                                             " and E " + std::to_string(channel.E.rows()) + "x" +
                                             std::to_string(channel.E.cols()), "robust");
  hinf::StateSpace t;
  t.A = cl.A;
  t.B = Eigen::MatrixXd::Zero(ncl, channel.H.cols());
  t.B.topRows(n) = channel.H;
  t.C = Eigen::MatrixXd::Zero(channel.E.rows(), ncl);
  t.C.leftCols(n) = channel.E;
  t.D = Eigen::MatrixXd::Zero(channel.E.rows(), channel.H.cols());
  return closed_loop_norm(t, P.time == hinf::TimeDomain::Discrete).norm;
}

ControllerCertificate certify_controller(const hinf::GeneralisedPlant& P, const hinf::Controller& K, double gamma,
                                         const ControllerChecks& checks) {
  require_controller_fits(P, K);
  ControllerCertificate c;
  const hinf::StateSpace cl = hinf::closed_loop(P, K);
  const Eigen::VectorXcd poles = balanced_eigenvalues(cl.A);
  c.closed_loop_poles.assign(poles.data(), poles.data() + poles.size());
  const bool discrete = P.time == hinf::TimeDomain::Discrete;
  c.stability_margin_value = discrete ? poles.cwiseAbs().maxCoeff() : poles.real().maxCoeff();
  c.stable = discrete ? c.stability_margin_value < 1 : c.stability_margin_value < 0;
  c.max_pole_modulus = poles.cwiseAbs().maxCoeff();
  c.poles_in_disk = !checks.pole_disk_radius || c.max_pole_modulus < *checks.pole_disk_radius;
  if (!c.stable) {
    c.closed_loop_hinf_norm = INFINITY;
    return c;
  }
  const HinfNorm h = closed_loop_norm(cl, discrete);
  c.closed_loop_hinf_norm = h.norm;
  c.peak_frequency = h.peak_frequency;
  if (checks.robust) {
    c.robust_channel_norm = robust_channel_norm(P, cl, *checks.robust);
    c.robustly_stable = *c.robust_channel_norm < 1;
  }
  c.passed = c.poles_in_disk && c.robustly_stable && c.closed_loop_hinf_norm <= gamma * (1 + kClosedLoopNormSlack);
  return c;
}

}  // namespace hinf::certify
