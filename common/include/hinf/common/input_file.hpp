// The one way an input file (config, gains file, scenario) is read: its exact bytes, from
// a regular file only, and never more than a cap per format, so that /dev/zero, a FIFO
// with no writer or a 50 MB file end as invalid input instead of a hang or an exhausted
// memory (docs/file-formats.md, "Limits").
#pragma once
#include <cstddef>
#include <string>

namespace hinf {

// Caps of the three formats (bytes). A config or gains file of the largest problem the
// solver takes (n = 60) is below 1 MiB; a scenario is a few kilobytes.
constexpr std::size_t kMaxConfigBytes = 16u << 20;
constexpr std::size_t kMaxGainsBytes = 16u << 20;
constexpr std::size_t kMaxScenarioBytes = 1u << 20;

// The bytes of `path`. Throws Error(InvalidInput) "cannot read <what> '<path>': <why>"
// when it does not exist, is not a regular file (a directory, a FIFO, a device, a
// socket: the FIFO is opened without blocking and refused), is larger than max_bytes,
// or a read fails (with errno's text).
std::string read_input_file(const std::string& path, const std::string& what, std::size_t max_bytes);

}  // namespace hinf
