// The controller file as text (docs/file-formats.md, format hinf-controller/1);
// hinf/common/atomic_file.hpp writes it. Same conventions as the gains file: deterministic
// (same result → same bytes) except the `timing:` section, last in the file.
#pragma once
#include <string>

#include "hinf/models/generalised_plant.hpp"
#include "hinf/synth/controller_synthesis.hpp"
#include "hinf/synth/gains_output.hpp"

namespace hinf::synth {

std::string format_controller_yaml(const ControllerSynthesisResult& result, const hinf::GeneralisedPlant& plant,
                                   const ControllerDesign& design, const GainsProvenance& provenance);

// The file's `certificate:` section alone at `gamma`, a YAML document of one key (verify's
// and check's JSON); `disk`: the design asks for a pole disk.
std::string controller_certificate_yaml(const ControllerCertificate& certificate, double gamma, bool discrete,
                                        bool disk);

}  // namespace hinf::synth
