// The problem kinds of the synthesis API (hinf/synth/api.hpp) and their registry
// (kind_registry.cpp). A kind is a folder synth/kinds/<name>/ that defines its
// `const ProblemKind& <name>_kind()`, declared below and listed in kind_registry.cpp.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "hinf/common/error.hpp"
#include "hinf/synth/api.hpp"

namespace hinf::synth {

struct ProblemKind {
  std::string_view name;
  // True if the config text is one of this kind's (decided from its top-level keys only;
  // text that is not YAML answers false and the filter kind's reader says why). The filter
  // kind, the registry's fallback, declares every config.
  bool (*declares)(const std::string& yaml_text);
  // Parses and validates a config of this kind (Error(InvalidInput) naming the key).
  std::unique_ptr<Problem> (*parse)(const std::string& yaml_text, const std::string& source_name);
};

// What every kind's Problem holds: its parsed config, whose `path`, `sha256` and
// `settings.verbose` answer the Problem's questions about itself.
template <class Config>
class ConfiguredProblem : public Problem {
 public:
  ConfiguredProblem(Config config, const ProblemKind& kind) : cfg_(std::move(config)), kind_(&kind) {}
  std::string_view kind() const final { return kind_->name; }
  const std::string& source() const final { return cfg_.path; }
  const std::string& sha256() const final { return cfg_.sha256; }
  bool verbose() const final { return cfg_.settings.verbose; }

 protected:
  // The config's settings with the caller's interruption poll handed to the solver.
  Settings settings_for(const JobObservers& observers) const {
    Settings s = cfg_.settings;
    s.solver.interrupted = observers.interrupted;
    return s;
  }
  const Config cfg_;

 private:
  const ProblemKind* kind_;
};

// The kinds (each defined in its folder; the registry lists them).
const ProblemKind& controller_kind();  // synth/kinds/controller/ (docs/maths.md §26)
const ProblemKind& filter_kind();      // synth/kinds/filter/: Theorem 1 or the observer form (§3, §18)

// The γ a file states (verify, check), or Error(InvalidInput) with `missing` as message.
inline double stated_gamma(const std::optional<double>& gamma, const std::string& missing) {
  if (!gamma) throw Error(ErrorCode::InvalidInput, missing);
  return *gamma;
}

}  // namespace hinf::synth
