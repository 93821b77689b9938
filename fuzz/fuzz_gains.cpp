// libFuzzer harness: the runtime's file readers (runtime/yaml) on arbitrary bytes — a gains
// file (hinf-gains/1), then the filter its loader builds (make_lti_filter, with D_F and G_F)
// stepped on a few samples; or, when the text names the format hinf-controller/1, a
// controller file. See fuzz_config.cpp for what counts as a finding.
#include <Eigen/Dense>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/runtime_yaml/controller_file.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/runtime_yaml/lti_filter_from_gains.hpp"

namespace {

// The loaded filter must run: init from z0 = 1, three steps with y = 1 (and u = 1).
void fly(const hinf::runtime_yaml::GainsFile& gains) {
  hinf::runtime::LtiFilter f = hinf::runtime_yaml::make_lti_filter(gains, "fuzz.yaml");
  f.init(Eigen::VectorXd::Ones(f.l()));
  const Eigen::VectorXd y = Eigen::VectorXd::Ones(f.m()), u = Eigen::VectorXd::Ones(f.r());
  for (int k = 0; k < 3; ++k) {
    if (f.r() > 0) f.step(y, u);
    else f.step(y);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    if (text.find("hinf-controller/1") != std::string::npos)
      hinf::runtime_yaml::parse_controller_yaml(text, "fuzz.yaml");
    else
      fly(hinf::runtime_yaml::parse_gains_yaml(text, "fuzz.yaml"));
  } catch (const hinf::Error&) {
  }
  return 0;
}
