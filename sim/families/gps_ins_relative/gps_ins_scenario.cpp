// GpsInsScenario's derived quantities (gps_ins_scenario.hpp), docs/maths.md §30.
#include "hinf/sim/gps_ins_scenario.hpp"

#include <cmath>

namespace hinf::sim {

Eigen::Vector3d GpsInsScenario::initial_velocity_used() const {
  if (!initial_velocity_drift_free) return initial_velocity;
  return Eigen::Vector3d(0, -2 * orbit_rate() * initial_position.x(), 0);
}

Eigen::Matrix3d GpsInsScenario::flyaround_frame() const {
  const Eigen::Vector3d x = initial_position.normalized();
  const Eigen::Vector3d z = initial_position.cross(initial_velocity_used()).normalized();
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = z.cross(x).transpose();
  R.row(2) = z.transpose();
  return R;
}

Eigen::Matrix3d GpsInsScenario::lvlh_from_inertial0() const {
  return models::rotation_3(arg_lat0) * models::rotation_1(inclination) * models::rotation_3(raan);
}

Eigen::Matrix3d GpsInsScenario::inertia_true() const {
  Eigen::Matrix3d J = inertia_nominal.asDiagonal();
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int k = 0; k < 3; ++k) {
    const int i = pairs[k][0], j = pairs[k][1];
    J(i, j) = J(j, i) =
        inertia_products_fraction * inertia_products_signs(k) * std::sqrt(inertia_nominal(i) * inertia_nominal(j));
  }
  return J;
}

std::array<Eigen::Vector3d, 3> GpsInsScenario::baselines() const {
  return {antennas[1] - antennas[0], antennas[2] - antennas[0], antennas[2] - antennas[1]};
}

std::array<Eigen::Vector3d, models::kGpsInsSatellites> GpsInsScenario::satellite_offsets() const {
  std::array<Eigen::Vector3d, models::kGpsInsSatellites> d;
  for (int j = 0; j < models::kGpsInsSatellites; ++j) {
    const double el = satellites_el_az[j](0), az = satellites_el_az[j](1);
    d[j] = satellite_distance * Eigen::Vector3d(std::sin(el), std::cos(el) * std::cos(az), std::cos(el) * std::sin(az));
  }
  return d;
}

models::GpsInsParameters GpsInsScenario::model_parameters(models::GpsInsJacobian jacobian) const {
  models::GpsInsParameters p;
  p.orbit_rate = orbit_rate();
  p.flyaround_rate = flyaround_rate();
  p.sample_time = sample_time;
  p.inertia = inertia_nominal_matrix();
  p.carrier_frequency = carrier_frequency;
  p.baselines = baselines();
  p.jacobian = jacobian;
  return p;
}

}  // namespace hinf::sim
