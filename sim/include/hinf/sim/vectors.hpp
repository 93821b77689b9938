// The simulator's fixed-size vectors (position/thrust, Hill state) and the truth model's
// names in hinf::sim.
#pragma once
#include <Eigen/Dense>

#include "hinf/models/two_body.hpp"

namespace hinf::sim {

using Vector3 = Eigen::Matrix<double, 3, 1>;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using hinf::models::kEarthMu;
using hinf::models::RelativeTwoBody;

}  // namespace hinf::sim
