// The registry of problem kinds (kinds.hpp): the kinds a config declares by its keys, in
// order — a new kind is one line here — and the filter kind for every config none of them
// declares (its reader then names what is wrong with it).
#include <array>

#include "hinf/synth/controller_config.hpp"
#include "kinds.hpp"

namespace hinf::synth {
namespace {

const ProblemKind& kind_of(const std::string& yaml_text) {
  static const std::array<const ProblemKind*, 1> declared = {&controller_kind()};
  for (const ProblemKind* kind : declared)
    if (kind->declares(yaml_text)) return *kind;
  return filter_kind();
}

}  // namespace

std::unique_ptr<Problem> parse_problem(const std::string& yaml_text, const std::string& source_name) {
  return kind_of(yaml_text).parse(yaml_text, source_name);
}

std::unique_ptr<Problem> load_problem(const std::string& path) { return parse_problem(read_config_bytes(path), path); }

}  // namespace hinf::synth
