// The relative GPS/INS model (models/gps_ins.hpp, docs/maths.md §29) against independent
// methods: central differences of the model's own f and h in error coordinates (the
// Jacobians, `full` and `paper`), a truth built from the inertial attitude and Euler's
// equation (the rate equation with W = +Ω×ν), and the CW fly-around in closed form.
#include <gtest/gtest.h>

#include <random>

#include "hinf/models/gps_ins.hpp"

using namespace hinf::models;
namespace ix = hinf::models::gps_ins_index;

namespace {
using GpsState = GpsInsProcess::State;
using Mat15 = GpsInsProcess::Jacobian;

Eigen::Vector3d unit(std::mt19937& g) {
  std::normal_distribution<double> nd;
  return Eigen::Vector3d(nd(g), nd(g), nd(g)).normalized();
}
Eigen::Matrix3d rotation(std::mt19937& g) {
  std::uniform_real_distribution<double> u(0, 3);
  return Eigen::AngleAxisd(u(g), unit(g)).toRotationMatrix();
}

// Rates far above the fly-around's (n ≈ 1e-3) so that every coupling term is visible.
GpsInsParameters fast_parameters(GpsInsJacobian jac, double dt,
                                 GpsInsPropagation propagation = GpsInsPropagation::Exact) {
  GpsInsParameters p;
  p.propagation = propagation;
  p.orbit_rate = 0.03;
  p.flyaround_rate = 0.02;
  p.sample_time = dt;
  p.inertia << 1000, 60, -50, 60, 1200, 40, -50, 40, 900;
  p.baselines = {Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(-2, 2, 0)};
  p.jacobian = jac;
  return p;
}

GpsInsEpoch random_epoch(std::mt19937& g) {
  GpsInsEpoch e;
  e.R_FR = rotation(g);
  e.R_RI = rotation(g);
  e.r_target = 6899807.0 * unit(g);
  for (auto& s : e.r_satellite) s = e.r_target + 2.0e7 * unit(g);
  return e;
}

// Random states; every other one with |σ| in [0.95, 0.999].
GpsState random_state(std::mt19937& g, int i) {
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  GpsState x;
  x.segment<3>(ix::kPosition) = 100.0 * Eigen::Vector3d(nd(g), nd(g), nd(g));
  x.segment<3>(ix::kVelocity) = 0.2 * Eigen::Vector3d(nd(g), nd(g), nd(g));
  const double norm = (i % 2) ? 0.95 + 0.049 * u(g) : 0.9 * u(g);
  x.segment<3>(ix::kAttitude) = norm * unit(g);
  x.segment<3>(ix::kRate) = 0.05 * Eigen::Vector3d(nd(g), nd(g), nd(g));
  x.segment<3>(ix::kBias) = 1e-5 * Eigen::Vector3d(nd(g), nd(g), nd(g));
  return x;
}

// Steps of the central differences per block: m, m/s, MRP, rad/s, rad/s.
double step(int k) {
  static const double h[5] = {1.0, 1e-3, 1e-6, 1e-6, 1e-6};
  return h[k / 3];
}
}  // namespace

TEST(GpsInsModel, BoxplusAndBoxminusAreInverse) {
  std::mt19937 g(1);
  for (int i = 0; i < 100; ++i) {
    const GpsState x = random_state(g, i);
    GpsState dx = 1e-2 * random_state(g, 0);
    dx.segment<3>(ix::kAttitude) *= 0.1;
    EXPECT_LE((gps_ins_boxminus(gps_ins_boxplus(x, dx), x) - dx).norm(), 1e-12 * (1 + dx.norm())) << i;
    // ⊞ composes the DCMs: R(σ ⊞ Δσ) = R(Δσ) R(σ)
    const Eigen::Matrix3d R = mrp_to_dcm(gps_ins_boxplus(x, dx).segment<3>(ix::kAttitude));
    EXPECT_LE((R - mrp_to_dcm(dx.segment<3>(ix::kAttitude)) * mrp_to_dcm(x.segment<3>(ix::kAttitude))).norm(), 1e-14);
  }
}

// C2: Φ against central differences of the step f in error coordinates, for the Euler step
// (188) with Φ = I + FΔt and for the RK4/CW step (188a) with its third-order Φ (Δt = 1 ms, so
// the O(Δt²) difference between I + FΔt and the Euler step's Jacobian is < 1e-7).
class GpsInsPropagationTest : public ::testing::TestWithParam<GpsInsPropagation> {};
INSTANTIATE_TEST_SUITE_P(Both, GpsInsPropagationTest,
                         ::testing::Values(GpsInsPropagation::Exact, GpsInsPropagation::Euler));

TEST_P(GpsInsPropagationTest, ProcessJacobianMatchesCentralDifferences) {
  std::mt19937 g(2);
  GpsInsProcess full(fast_parameters(GpsInsJacobian::Full, 1e-3, GetParam()));
  GpsInsProcess paper(fast_parameters(GpsInsJacobian::Paper, 1e-3, GetParam()));
  double worst_full = 0, least_paper = 1e300;
  for (int i = 0; i < 100; ++i) {
    const GpsInsEpoch e = random_epoch(g);
    full.set_epoch(e);
    paper.set_epoch(e);
    const GpsState x = random_state(g, i);
    const Eigen::Vector3d T = 5.0 * unit(g);
    Mat15 fd;
    for (int k = 0; k < 15; ++k) {
      GpsState d = GpsState::Zero();
      d(k) = step(k);
      fd.col(k) = gps_ins_boxminus(full.f(gps_ins_boxplus(x, d), T), full.f(gps_ins_boxplus(x, GpsState(-d)), T)) /
                  (2 * step(k));
    }
    const double err_full = (fd - full.F(x, T)).cwiseAbs().maxCoeff();
    worst_full = std::max(worst_full, err_full);
    least_paper = std::min(least_paper, (fd - paper.F(x, T)).cwiseAbs().maxCoeff());
    EXPECT_LE(err_full, 1e-6 * fd.cwiseAbs().maxCoeff()) << "state " << i << ", |σ| = "
                                                          << x.segment<3>(ix::kAttitude).norm();
  }
  // the printed Jacobian misses terms of the size of the rates: the check sees them
  EXPECT_GT(least_paper, 10 * worst_full);
}

// ∂h/∂Δx by central differences of h in error coordinates.
template <class Measurement>
Eigen::Matrix<double, Measurement::NZ, 15> h_central_differences(const Measurement& m, const GpsState& x) {
  Eigen::Matrix<double, Measurement::NZ, 15> fd;
  for (int k = 0; k < 15; ++k) {
    GpsState d = GpsState::Zero();
    d(k) = step(k);
    fd.col(k) = (m.h(gps_ins_boxplus(x, d)) - m.h(gps_ins_boxplus(x, GpsState(-d)))) / (2 * step(k));
  }
  return fd;
}

// H against its central differences fd, block by block: the gyro rows, the pseudorange rows
// and the phase rows, each against each 3-column state block, within 1e-6 relative.
template <int NZ>
void expect_jacobian_blocks_match(const Eigen::Matrix<double, NZ, 15>& fd, const Eigen::Matrix<double, NZ, 15>& H,
                                  int state) {
  for (const auto& [r0, nr] : {std::pair{0, 3}, std::pair{3, 4}, std::pair{7, NZ - 7}})
    for (int c0 = 0; c0 < 15; c0 += 3) {
      const Eigen::MatrixXd a = fd.block(r0, c0, nr, 3), b = H.block(r0, c0, nr, 3);
      EXPECT_LE((a - b).norm(), 1e-6 * b.norm() + 1e-12) << "state " << state << " rows " << r0 << " cols " << c0;
    }
}

// C2: H against central differences of h, block by block (the phase rows' position block is
// ~1e-7 of their attitude block and is checked on its own).
TEST(GpsInsModel, MeasurementJacobianMatchesCentralDifferences) {
  std::mt19937 g(3);
  GpsInsMeasurement full(fast_parameters(GpsInsJacobian::Full, 1.0));
  GpsInsMeasurement paper(fast_parameters(GpsInsJacobian::Paper, 1.0));
  constexpr int NZ = GpsInsMeasurement::NZ;
  for (int i = 0; i < 100; ++i) {
    const GpsInsEpoch e = random_epoch(g);
    full.set_epoch(e);
    paper.set_epoch(e);
    const GpsState x = random_state(g, i);
    const Eigen::Matrix<double, NZ, 15> fd = h_central_differences(full, x);
    expect_jacobian_blocks_match(fd, full.H(x), i);
    // `paper` drops the gyro's attitude block 4[(Ω+ν)×]; the differences see it
    const Eigen::Matrix3d gyro_fd = fd.block(0, ix::kAttitude, 3, 3);
    const Eigen::Matrix3d gyro_paper = paper.H(x).block(0, ix::kAttitude, 3, 3);
    EXPECT_GT((gyro_fd - gyro_paper).norm(), 0.1 * gyro_fd.norm());
  }
}

// (193a): the double differences are each baseline's phase rows minus its satellite-0 row
// (the gyro and pseudorange rows unchanged), their H matches central differences of their h,
// and independent single-difference phase noise σ² becomes σ²(I + 11ᵀ) within each baseline's
// three rows, 0 across baselines.
TEST(GpsInsModel, DoubleDifferencesAreSatelliteDifferencesWithCorrelatedNoise) {
  std::mt19937 g(9);
  GpsInsMeasurement single(fast_parameters(GpsInsJacobian::Full, 1.0));
  GpsInsDoubleDifferenceMeasurement dd(fast_parameters(GpsInsJacobian::Full, 1.0));
  constexpr int NZ = GpsInsDoubleDifferenceMeasurement::NZ;
  static_assert(NZ == 16);
  for (int i = 0; i < 20; ++i) {
    const GpsInsEpoch e = random_epoch(g);
    single.set_epoch(e);
    dd.set_epoch(e);
    const GpsState x = random_state(g, i);
    const auto zs = single.h(x);
    const auto zd = dd.h(x);
    EXPECT_EQ(zd.head<7>(), zs.head<7>());
    for (int k = 0; k < 3; ++k)
      for (int j = 1; j < 4; ++j) EXPECT_EQ(zd(7 + 3 * k + j - 1), zs(7 + 4 * k + j) - zs(7 + 4 * k)) << k << " " << j;
    const Eigen::Matrix<double, NZ, 15> fd = h_central_differences(dd, x);
    expect_jacobian_blocks_match(fd, dd.H(x), i);
  }
  const double sigma2 = 0.0028 * 0.0028;
  Eigen::Matrix<double, 19, 19> R = Eigen::Matrix<double, 19, 19>::Zero();
  R.diagonal().tail<12>().setConstant(sigma2);
  const auto D = GpsInsDoubleDifferenceMeasurement::map();
  const Eigen::Matrix<double, 16, 16> R_dd = D * R * D.transpose();
  Eigen::Matrix<double, 16, 16> expected = Eigen::Matrix<double, 16, 16>::Zero();
  for (int k = 0; k < 3; ++k)
    expected.block<3, 3>(7 + 3 * k, 7 + 3 * k) = sigma2 * (Eigen::Matrix3d::Identity() + Eigen::Matrix3d::Ones());
  EXPECT_EQ(R_dd, expected);
}

// C3: the model's ω̇ (with W = +Ω×ν) is the derivative of ω = ω_BI − Ω − ν along a truth
// made of the inertial attitude (Ṙ_BI = −[ω_BI×]R_BI, Euler's equation, RK4) and the frames
// R_FR(t) = R3(n_f t) R_FR(0), R_RI(t) = R3(n t) R_RI(0).
TEST(GpsInsModel, RateEquationIsTheDerivativeOfTheTruth) {
  std::mt19937 g(4);
  const GpsInsParameters p = fast_parameters(GpsInsJacobian::Full, 1.0);
  GpsInsProcess model(p);
  const Eigen::Matrix3d J_inv = p.inertia.inverse();
  const Eigen::Vector3d T = 3.0 * unit(g);
  const Eigen::Matrix3d R_FR0 = rotation(g), R_RI0 = rotation(g);
  struct Truth {
    Eigen::Matrix3d R_BI;
    Eigen::Vector3d w_BI;
  };
  auto derivative = [&](const Truth& s) {
    return Truth{-cross_matrix(s.w_BI) * s.R_BI, J_inv * (T - s.w_BI.cross(p.inertia * s.w_BI))};
  };
  auto rk4 = [&](Truth s, double h) {
    auto add = [](const Truth& a, const Truth& b, double c) { return Truth{a.R_BI + c * b.R_BI, a.w_BI + c * b.w_BI}; };
    const Truth k1 = derivative(s), k2 = derivative(add(s, k1, h / 2)), k3 = derivative(add(s, k2, h / 2)),
                k4 = derivative(add(s, k3, h));
    s.R_BI += h / 6 * (k1.R_BI + 2 * k2.R_BI + 2 * k3.R_BI + k4.R_BI);
    s.w_BI += h / 6 * (k1.w_BI + 2 * k2.w_BI + 2 * k3.w_BI + k4.w_BI);
    return s;
  };
  auto frames = [&](double t) {
    GpsInsEpoch e;
    e.R_FR = rotation_3(p.flyaround_rate * t) * R_FR0;
    e.R_RI = rotation_3(p.orbit_rate * t) * R_RI0;
    return e;
  };
  // σ and ω of the truth at t
  auto relative = [&](const Truth& s, double t) {
    const GpsInsEpoch e = frames(t);
    const Eigen::Vector3d sigma = mrp_from_dcm(s.R_BI * e.R_RI.transpose() * e.R_FR.transpose());
    const GpsInsRates r = gps_ins_rates(p, e.R_FR, sigma, Eigen::Vector3d::Zero());
    return std::pair{sigma, Eigen::Vector3d(s.w_BI - r.Omega - r.nu)};
  };
  const double h = 1e-3;
  for (int i = 0; i < 20; ++i) {
    const double t = 10.0 * i;
    const Truth s{rotation(g).transpose(), 0.05 * unit(g)};
    const auto [sigma, w] = relative(s, t);
    const Eigen::Vector3d w_dot_fd = (relative(rk4(s, h), t + h).second - relative(rk4(s, -h), t - h).second) / (2 * h);
    model.set_epoch(frames(t));
    GpsState x = GpsState::Zero();
    x.segment<3>(ix::kAttitude) = sigma;
    x.segment<3>(ix::kRate) = w;
    const Eigen::Vector3d w_dot = model.rate_derivative(x, T);
    EXPECT_LE((w_dot - w_dot_fd).norm(), 1e-7 * w_dot.norm()) << i;
    // the printed sign of W is off by 2|Ω×ν|
    const GpsInsRates r = gps_ins_rates(p, frames(t).R_FR, sigma, w);
    EXPECT_GT((w_dot - 2 * r.Omega.cross(r.nu) - w_dot_fd).norm(), 1e3 * (w_dot - w_dot_fd).norm());
  }
}

// The CW part of f is the paper's (10); in closed form the drift-free circle keeps |ρ| = 200 m,
// and the exact step moves along it.
TEST(GpsInsModel, TranslationIsTheCwMatrix) {
  GpsInsParameters p = fast_parameters(GpsInsJacobian::Full, 1.0);
  p.orbit_rate = 1.101573e-3;
  const GpsInsProcess model(p);
  const auto A = model.translation_matrix();
  const double n = p.orbit_rate, t = 1234.5;
  // x = (r/2) cos nt, y = −r sin nt, z = −(√3/2) r cos nt satisfies ẍ = A x exactly
  const double r = 200;
  Eigen::Matrix<double, 6, 1> s, s_dot;
  s << r / 2 * std::cos(n * t), -r * std::sin(n * t), -std::sqrt(3.0) / 2 * r * std::cos(n * t),
      -r / 2 * n * std::sin(n * t), -r * n * std::cos(n * t), std::sqrt(3.0) / 2 * r * n * std::sin(n * t);
  s_dot << s.tail<3>(), -r / 2 * n * n * std::cos(n * t), r * n * n * std::sin(n * t),
      std::sqrt(3.0) / 2 * r * n * n * std::cos(n * t);
  EXPECT_LE((A * s - s_dot).norm(), 1e-15 * r);
  EXPECT_NEAR(s.head<3>().norm(), r, 1e-12);
  // exp(F_ρ Δt) carries the closed form from t to t + Δt
  const double T = p.sample_time;
  Eigen::Matrix<double, 6, 1> s1;
  s1 << r / 2 * std::cos(n * (t + T)), -r * std::sin(n * (t + T)), -std::sqrt(3.0) / 2 * r * std::cos(n * (t + T)),
      -r / 2 * n * std::sin(n * (t + T)), -r * n * std::cos(n * (t + T)), std::sqrt(3.0) / 2 * r * n * std::sin(n * (t + T));
  EXPECT_LE((model.translation_transition() * s - s1).norm(), 1e-12 * r);
}

// The shadow-set switch leaves R(σ) unchanged, so the body-frame error of any nearby state
// is unchanged: the switch's Jacobian in error coordinates is the identity and P stays.
TEST(GpsInsModel, ShadowSwitchKeepsTheDcmAndTheErrorCovariance) {
  std::mt19937 g(5);
  const GpsInsProcess model(fast_parameters(GpsInsJacobian::Full, 1.0));
  for (int i = 0; i < 50; ++i) {
    GpsState x = random_state(g, 1);
    x.segment<3>(ix::kAttitude) = mrp_shadow(x.segment<3>(ix::kAttitude));  // |σ| > 1
    GpsState xs = x;
    Mat15 P = Mat15::Identity() * 3.0;
    model.normalise(xs, P);
    EXPECT_LE(xs.segment<3>(ix::kAttitude).norm(), 1.0);
    EXPECT_LE((mrp_to_dcm(xs.segment<3>(ix::kAttitude)) - mrp_to_dcm(x.segment<3>(ix::kAttitude))).norm(), 1e-14);
    EXPECT_EQ(P, Mat15::Identity() * 3.0);
    // error of a perturbed truth relative to x and to its switched copy: the same
    GpsState d = GpsState::Zero();
    d.segment<3>(ix::kAttitude) = 1e-3 * unit(g);
    const GpsState truth = gps_ins_boxplus(x, d);
    EXPECT_LE((gps_ins_boxminus(truth, xs) - gps_ins_boxminus(truth, x)).norm(), 1e-12);  // rounding
  }
}

TEST(GpsInsModel, ProcessNoiseAndRekfUncertaintyHaveTheDocumentedBlocks) {
  GpsInsParameters p = fast_parameters(GpsInsJacobian::Full, 2.0);
  GpsInsProcessNoise q;
  q.accel_sigma = 1e-6;
  q.torque_sigma = 1e-6;
  q.bias_walk_sigma = 2.424e-9;
  const auto Q = gps_ins_process_noise(p, q, Eigen::Vector3d(0.01, 0, 0));
  EXPECT_NEAR(Q(ix::kVelocity, ix::kVelocity), 4e-12, 1e-26);
  EXPECT_NEAR(Q(ix::kBias, ix::kBias), 2.424e-9 * 2.424e-9 * 2, 1e-30);
  const Eigen::Matrix3d Ji = p.inertia.inverse();
  EXPECT_LE((Q.block<3, 3>(ix::kRate, ix::kRate) - 4 * 1e-12 * Ji * Ji.transpose()).norm(), 1e-30);
  EXPECT_EQ(Q.block(ix::kPosition, ix::kPosition, 3, 3).norm(), 0.0);
  q.zoh = true;
  const auto Qz = gps_ins_process_noise(p, q, Eigen::Vector3d(0.01, 0, 0));
  // an acceleration held over Δt = 2: Δρ = a Δt²/2, Δρ̇ = a Δt
  EXPECT_NEAR(Qz(ix::kPosition, ix::kPosition), 1e-12 * 16 / 4, 1e-26);
  EXPECT_NEAR(Qz(ix::kPosition, ix::kVelocity), 1e-12 * 8 / 2, 1e-26);
  // the inertia term: N_f = (p_f max J_ii |ω_BI|²)²
  q.zoh = false;
  q.torque_sigma = 0;
  q.inertia_uncertainty_fraction = 0.3;
  const auto Qf = gps_ins_process_noise(p, q, Eigen::Vector3d(0.01, 0, 0));
  const double nf = 0.3 * 1200 * 1e-4;
  EXPECT_LE((Qf.block<3, 3>(ix::kRate, ix::kRate) - 4 * nf * nf * Ji * Ji.transpose()).norm(), 1e-20);

  GpsInsProcess model(p);
  GpsInsMeasurement meas(p);
  std::mt19937 g(6);
  const GpsInsEpoch e = random_epoch(g);
  model.set_epoch(e);
  meas.set_epoch(e);
  const GpsState x = random_state(g, 0);
  GpsState s;
  s.setConstant(2.0);
  const auto u = gps_ins_rekf_uncertainty(model.continuous_jacobian(x), meas.H(x), s, 2.0, 0.1, 1e-3);
  // A_k = κ_A Δt F_rate diag(s): only the rate equation's rows (197)
  EXPECT_EQ(u.A.topRows<9>().norm(), 0.0);
  EXPECT_EQ(u.A.bottomRows<3>().norm(), 0.0);
  const Eigen::Matrix<double, 3, 15> F_rate = model.continuous_jacobian(x).middleRows<3>(ix::kRate);
  EXPECT_GT(F_rate.norm(), 0.0);
  EXPECT_LE((u.A.middleRows<3>(ix::kRate) - 0.1 * 2.0 * F_rate * 2.0).norm(), 1e-15 * F_rate.norm());
  GpsState L_diag = GpsState::Zero();
  L_diag.segment<6>(ix::kAttitude).setConstant(0.5);  // σ and ω only
  EXPECT_EQ(u.L, Mat15(L_diag.asDiagonal()));
  const auto H = meas.H(x);
  EXPECT_LE((u.C * u.C.transpose() - 1e-6 * 4 * H * H.transpose()).norm(), 1e-12 * (H * H.transpose()).norm());
}
