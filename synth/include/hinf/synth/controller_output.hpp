// The controller file as text (docs/file-formats.md, format hinf-controller/1);
// hinf/common/atomic_file.hpp writes it. Same conventions as the gains file: deterministic
// (same result → same bytes) except the `timing:` section, last in the file.
#pragma once
#include <optional>
#include <string>

#include "hinf/models/generalised_plant.hpp"
#include "hinf/synth/controller_synthesis.hpp"
#include "hinf/synth/gains_output.hpp"

namespace hinf::synth {

std::string format_controller_yaml(const ControllerSynthesisResult& result, const hinf::GeneralisedPlant& plant,
                                   const ControllerDesign& design, const GainsProvenance& provenance);

// A continuous-time controller discretised at the sampled plant's period (docs/maths.md
// (161)–(161c)): the discrete controller file, `gamma` the sampled loop's certified ℓ2 gain,
// `certificate` its certificate on `sampled` (the plant sampled by a zero-order hold), the
// `discretised:` section saying how. Deterministic: no `timing:` section.
struct DiscretisedController {
  hinf::Controller controller;
  bool strictly_proper = true;
  const char* method = "tustin";           // tustin | zoh
  std::optional<double> continuous_gamma;  // the continuous file's γ
  double gamma = 0;
  ControllerCertificate certificate;
};
std::string format_discretised_controller_yaml(const DiscretisedController& k, const hinf::GeneralisedPlant& sampled,
                                               const GainsProvenance& provenance);

// The file's `certificate:` section alone at `gamma`, a YAML document of one key (verify's
// and check's JSON); `disk`: the design asks for a pole disk.
std::string controller_certificate_yaml(const ControllerCertificate& certificate, double gamma, bool discrete,
                                        bool disk);

}  // namespace hinf::synth
