// Umbrella header for the Eigen-only runtime: filters and models.
#pragma once

#include "hinf/runtime/ekf.hpp"
#include "hinf/runtime/filter_status.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/models/cartesian_position.hpp"
#include "hinf/models/hill.hpp"
#include "hinf/models/linear.hpp"
#include "hinf/models/range_azimuth_elevation.hpp"
#include "hinf/runtime/rekf.hpp"
