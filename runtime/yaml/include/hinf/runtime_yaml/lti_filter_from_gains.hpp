// A runtime LtiFilter (runtime/include/hinf/runtime/lti_filter.hpp) from a gains file.
#pragma once
#include <stdexcept>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"

namespace hinf::runtime_yaml {

// Builds the filter docs/maths.md (5)-(6) from `gains`, all of it: the filtered estimate's
// feedthrough D_F (140) and the known input's G_F (121) when the file has them (then the
// filter's step(y, u) must be used; step(y) refuses it). The LtiFilter constructor's checks
// (shapes, finiteness, Schur stability of A_F) surface as hinf::Error (InvalidInput),
// prefixed with `source_name` (e.g. the file path) when given.
inline runtime::LtiFilter make_lti_filter(const GainsFile& gains,
                                          const std::string& source_name = "") {
  const Eigen::MatrixXd none_known = Eigen::MatrixXd::Zero(gains.A_F.rows(), 0);
  try {
    return runtime::LtiFilter(gains.A_F, gains.B_F, gains.C_F, gains.G_F.size() > 0 ? gains.G_F : none_known,
                              gains.filtered ? gains.D_F : Eigen::MatrixXd(0, 0));
  } catch (const std::invalid_argument& e) {
    throw Error(ErrorCode::InvalidInput,
                (source_name.empty() ? std::string() : source_name + ": ") + "filter: " + e.what());
  }
}

}  // namespace hinf::runtime_yaml
