// The manifold hooks of Ekf/Rekf (detail/kalman_core.hpp, docs/maths.md (194), (195)):
// an additive boxplus reproduces the vector update bit for bit; normalise runs after every
// step; on the 15-state GPS/INS model the REKF with A_k = C_k = L = 0 is the EKF (C1).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "hinf/models/cartesian_position.hpp"
#include "hinf/models/gps_ins.hpp"
#include "hinf/models/hill.hpp"
#include "hinf/runtime/ekf.hpp"
#include "hinf/runtime/rekf.hpp"

using namespace hinf::runtime;
using hinf::models::CartesianPosition;
using hinf::models::HillModel;

namespace {
// The Hill model with the hooks written out for a vector space.
struct HillWithHooks : HillModel {
  using HillModel::HillModel;
  State boxplus(const State& x, const State& dx) const { return x + dx; }
  void normalise(State& /*x*/, Eigen::Matrix<double, 6, 6>& /*P*/) const { ++*normalise_calls; }
  long* normalise_calls = nullptr;
};

template <class A, class B>
bool same_bits(const A& a, const B& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

HillModel::Gain gain() {
  HillModel::Gain K = HillModel::Gain::Zero();
  K.leftCols<3>() = -2.25 * Eigen::Matrix3d::Identity();
  K.rightCols<3>() = -23.0 * Eigen::Matrix3d::Identity();
  return K;
}
}  // namespace

TEST(ManifoldHooks, AdditiveBoxplusIsBitForBitTheVectorUpdate) {
  const HillModel plain(7.2722e-5, 1000.0, 0.1, gain());
  HillWithHooks hooked(7.2722e-5, 1000.0, 0.1, gain());
  long calls = 0;
  hooked.normalise_calls = &calls;
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  const Mat6 Q = 1e-4 * Mat6::Identity();
  const Eigen::Matrix3d R = 0.01 * Eigen::Matrix3d::Identity();
  Ekf<HillModel, CartesianPosition> ekf(plain, {}, Q, R);
  Ekf<HillWithHooks, CartesianPosition> ekf_h(hooked, {}, Q, R);
  Mat6 A = Mat6::Zero();
  A.diagonal().setConstant(0.01);
  Rekf<HillModel, CartesianPosition> rekf(plain, {}, Q, R, 2.0, A, 0.1 * Eigen::Matrix3d::Identity(), A);
  Rekf<HillWithHooks, CartesianPosition> rekf_h(hooked, {}, Q, R, 2.0, A, 0.1 * Eigen::Matrix3d::Identity(), A);
  Eigen::Matrix<double, 6, 1> x0;
  x0 << 630, 520, 1000, 0.1, -0.2, 0.05;
  const Mat6 P0 = 100 * Mat6::Identity();
  ekf.init(x0, P0);
  ekf_h.init(x0, P0);
  rekf.init(x0, P0);
  rekf_h.init(x0, P0);
  std::mt19937 g(7);
  std::normal_distribution<double> nd;
  for (int k = 0; k < 1000; ++k) {
    const Eigen::Vector3d u(nd(g), nd(g), nd(g));
    const Eigen::Vector3d y = Eigen::Vector3d(600, 550, 1040) + 3.0 * Eigen::Vector3d(nd(g), nd(g), nd(g));
    ASSERT_EQ(ekf.predict(u), FilterStatus::Ok);
    ASSERT_EQ(ekf_h.predict(u), FilterStatus::Ok);
    ASSERT_EQ(rekf.predict(u), RekfStatus::Ok);
    ASSERT_EQ(rekf_h.predict(u), RekfStatus::Ok);
    ASSERT_EQ(ekf.update(y), FilterStatus::Ok);
    ASSERT_EQ(ekf_h.update(y), FilterStatus::Ok);
    ASSERT_EQ(rekf.update(y), RekfStatus::Ok);
    ASSERT_EQ(rekf_h.update(y), RekfStatus::Ok);
    ASSERT_TRUE(same_bits(ekf.x(), ekf_h.x()) && same_bits(ekf.P(), ekf_h.P())) << "EKF, step " << k;
    ASSERT_TRUE(same_bits(rekf.x(), rekf_h.x()) && same_bits(rekf.P(), rekf_h.P())) << "REKF, step " << k;
  }
  EXPECT_EQ(calls, 4 * 1000);  // after every predict and every update of both filters
}

namespace {
namespace ix = hinf::models::gps_ins_index;
using hinf::models::GpsInsMeasurement;
using hinf::models::GpsInsProcess;
using GState = GpsInsProcess::State;
using Mat15 = GpsInsProcess::Jacobian;
constexpr int NZ = GpsInsMeasurement::NZ;

hinf::models::GpsInsParameters flyaround_parameters() {
  hinf::models::GpsInsParameters p;
  p.orbit_rate = 1.101573e-3;
  p.flyaround_rate = p.orbit_rate;
  p.sample_time = 1.0;
  p.inertia = Eigen::Vector3d(1000, 1200, 900).asDiagonal();
  p.baselines = {Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(-2, 2, 0)};
  return p;
}

// The epoch at t: frames turning at n_f and n, satellites fixed in LVLH.
hinf::models::GpsInsEpoch epoch_at(const hinf::models::GpsInsParameters& p, double t) {
  using hinf::models::rotation_3;
  hinf::models::GpsInsEpoch e;
  e.R_FR = rotation_3(p.flyaround_rate * t);
  e.R_RI = rotation_3(p.orbit_rate * t);
  e.r_target = e.R_RI.transpose() * Eigen::Vector3d(6899807.0, 0, 0);
  const Eigen::Vector3d d[4] = {{1, 0, 0}, {0.5, 0.866, 0}, {0.5, -0.433, 0.75}, {0.5, -0.433, -0.75}};
  for (int j = 0; j < 4; ++j) e.r_satellite[j] = e.r_target + e.R_RI.transpose() * (2.0e7 * d[j]);
  return e;
}
}  // namespace

// C1: with A_k = C_k = L = 0 the REKF is the EKF on the 15-state model (boxplus, normalise,
// a time-varying epoch), states and P within 1e-12 relative over 1000 steps.
TEST(ManifoldHooks, GpsInsRekfWithoutUncertaintyIsTheEkf) {
  const auto p = flyaround_parameters();
  const GpsInsProcess process(p);
  const GpsInsMeasurement meas(p);
  Mat15 Q = Mat15::Zero();
  Q.diagonal() << 0, 0, 0, 1e-12, 1e-12, 1e-12, 0, 0, 0, 1e-18, 1e-18, 1e-18, 6e-18, 6e-18, 6e-18;
  Eigen::Matrix<double, NZ, NZ> R = Eigen::Matrix<double, NZ, NZ>::Zero();
  R.diagonal().head<3>().setConstant(2.424e-7 * 2.424e-7);
  R.diagonal().segment<4>(3).setConstant(1.0);
  R.diagonal().tail<12>().setConstant(0.0028 * 0.0028);
  Ekf<GpsInsProcess, GpsInsMeasurement> ekf(process, meas, Q, R);
  Rekf<GpsInsProcess, GpsInsMeasurement> rekf(process, meas, Q, R, 1.0, Mat15::Zero(),
                                              Eigen::Matrix<double, NZ, NZ>::Zero(), Mat15::Zero());
  GState truth = GState::Zero();
  truth.head<6>() << 100, 0, -173.21, 0, -0.22031, 0;
  truth.segment<3>(ix::kAttitude) << 0.00815, 0.013464, 0.022043;
  truth.segment<3>(ix::kBias).setConstant(5.0 / 3600 * hinf::models::kRadiansPerDegree);
  GState x0 = truth;
  x0.head<3>() += Eigen::Vector3d(8, -5, 3);
  x0.segment<3>(ix::kAttitude) += Eigen::Vector3d(0.002, -0.001, 0.001);
  x0.segment<3>(ix::kBias).setZero();
  Mat15 P0 = Mat15::Zero();
  P0.diagonal() << 100, 100, 100, 1e-4, 1e-4, 1e-4, 2e-5, 2e-5, 2e-5, 3e-8, 3e-8, 3e-8, 6e-10, 6e-10, 6e-10;
  ekf.init(x0, P0);
  rekf.init(x0, P0);
  std::mt19937 g(11);
  std::normal_distribution<double> nd;
  GpsInsProcess truth_model(p);
  const Eigen::Vector3d T_c(1e-3, -2e-3, 5e-4);
  for (int k = 0; k < 1000; ++k) {
    const double t = k * p.sample_time;
    for (auto* m : {&truth_model, &ekf.mutable_model(), &rekf.mutable_model()}) m->set_epoch(epoch_at(p, t));
    truth = truth_model.f(truth, T_c);
    ASSERT_EQ(ekf.predict(T_c), FilterStatus::Ok) << k;
    ASSERT_EQ(rekf.predict(T_c), RekfStatus::Ok) << k;
    const auto e1 = epoch_at(p, t + p.sample_time);
    for (auto* m : {&ekf.mutable_measurement(), &rekf.mutable_measurement()}) m->set_epoch(e1);
    GpsInsMeasurement truth_meas(p);
    truth_meas.set_epoch(e1);
    GpsInsMeasurement::Vector y = truth_meas.h(truth);
    for (int i = 0; i < NZ; ++i) y(i) += std::sqrt(R(i, i)) * nd(g);
    ASSERT_EQ(ekf.update(y), FilterStatus::Ok) << k;
    ASSERT_EQ(rekf.update(y), RekfStatus::Ok) << k;
    ASSERT_LE((rekf.x() - ekf.x()).norm(), 1e-12 * ekf.x().norm()) << k;
    ASSERT_LE((rekf.P() - ekf.P()).norm(), 1e-12 * ekf.P().norm()) << k;
  }
  // and the filter converged: position within 1 m, attitude within 0.01°
  EXPECT_LE((ekf.x().head<3>() - truth.head<3>()).norm(), 1.0);
  EXPECT_LE(4 * hinf::models::gps_ins_boxminus(ekf.x(), truth).segment<3>(ix::kAttitude).norm() /
                hinf::models::kRadiansPerDegree,
            0.01);
}

// normalise runs after predict: a state on the far set (|σ| > 1) comes back to the short one
// with the same DCM and the same P.
TEST(ManifoldHooks, GpsInsPredictSwitchesToTheShortSet) {
  const auto p = flyaround_parameters();
  Ekf<GpsInsProcess, GpsInsMeasurement> ekf(GpsInsProcess{p}, GpsInsMeasurement{p}, Mat15::Zero(),
                                            Eigen::Matrix<double, NZ, NZ>::Identity());
  GState x = GState::Zero();
  x.segment<3>(ix::kAttitude) = hinf::models::mrp_shadow(Eigen::Vector3d(0.3, -0.2, 0.1));
  ekf.init(x, Mat15::Identity());
  ekf.mutable_model().set_epoch(epoch_at(p, 0));
  const GState predicted = ekf.model().f(x, Eigen::Vector3d::Zero());
  ASSERT_GT(predicted.segment<3>(ix::kAttitude).norm(), 1.0);
  ASSERT_EQ(ekf.predict(Eigen::Vector3d::Zero()), FilterStatus::Ok);
  EXPECT_LE(ekf.x().segment<3>(ix::kAttitude).norm(), 1.0);
  EXPECT_LE((hinf::models::mrp_to_dcm(ekf.x().segment<3>(ix::kAttitude)) -
             hinf::models::mrp_to_dcm(predicted.segment<3>(ix::kAttitude)))
                .norm(),
            1e-14);
}
