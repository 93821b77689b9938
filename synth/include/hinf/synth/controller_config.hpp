// Reading a controller config (docs/file-formats.md, "Controller config"): strict YAML with
// `controller:` — the generalised plant of docs/maths.md (145) as matrices, its time domain
// and the controller's structure — and optional `solver:` settings.
//   controller:
//     time: continuous | discrete        (required)
//     sample_time: 0.1                   (s; discrete time only, required there)
//     A, B1, B2, C1, C2, D12, D21        (required)
//     D11                                (optional; zero by default)
//     strictly_proper: true              (default true: D_K = 0)
//     pole_disk_radius: 2                (optional: closed-loop poles in |λ| < r; rad/s, or
//                                         a modulus < 1 in discrete time)
// Every failure is Error(InvalidInput) naming the file, the key path and, for matrices,
// the expected and actual dimensions.
#pragma once
#include <string>

#include "hinf/models/generalised_plant.hpp"
#include "hinf/synth/controller_synthesis.hpp"
#include "hinf/synth/settings.hpp"

namespace hinf::synth {

struct ControllerConfig {
  hinf::GeneralisedPlant plant;
  ControllerDesign design;
  Settings settings;
  std::string sha256;  // of the config's exact bytes
  std::string path;
};

ControllerConfig parse_controller_config(const std::string& yaml_text, const std::string& source_name);

// True if the YAML text is a map with a top-level `controller:` key (a controller config);
// false for anything else, including text that is not YAML (parse_config then says why).
bool declares_controller(const std::string& yaml_text);

// The exact bytes of a config file (size-capped, regular files only; Error(InvalidInput)).
std::string read_config_bytes(const std::string& path);

}  // namespace hinf::synth
