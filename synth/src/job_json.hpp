// The JSON a job returns beside its report (api.hpp: SolveOutcome::json, …; `hinf-synth
// COMMAND --json`): one object per job, led by `schema` ("hinf-synth.<job>/1") and the
// problem's kind, every number a double written so that it reads back bit for bit, a
// non-finite one as null. Where a job's result is a file the tool writes (a gains or
// controller file, its certificate section), the JSON holds that file's own keys and
// values, converted from its YAML: one home for the names, docs/file-formats.md.
#pragma once
#include <string>
#include <string_view>

#include "report_text.hpp"

namespace hinf::synth::job_json {

// The version of every job's JSON layout (the `schema` key's suffix).
inline constexpr int kSchemaVersion = 1;

// {"schema": "hinf-synth.<job>/1", "kind": kind, "config": config_source}.
Json envelope(std::string_view job, std::string_view kind, const std::string& config_source);

// A YAML document written by this tool (yaml_emit.hpp) as JSON, keys in the file's order:
// plain scalars that read as YAML booleans, nulls or numbers become those (.nan and ±.inf
// null), quoted scalars and every other plain scalar strings.
Json from_yaml(const std::string& yaml_text);

// solve and kalman: the envelope, gamma, what the file holds ("gains", "controller") and the
// file itself as JSON under "file".
std::string solved(std::string_view job, std::string_view kind, const std::string& config_source, double gamma,
                   const std::string& file_contents, const std::string& file_text);

}  // namespace hinf::synth::job_json
