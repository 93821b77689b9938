// Parameter studies of a config (docs/maths.md §21): the certified γ against one number of
// the config (`hinf-synth sweep --param`), and the largest value of it for which a
// certified filter exists, by bisection (`--max-feasible`).
//
// Every point is a full `synthesize` — pre-flight, solve, recovery, the independent
// certificate — so a point's γ is certified exactly as `solve`'s is, and its outcome is the
// exit code `solve` would give there.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hinf/common/error.hpp"
#include "hinf/synth/config.hpp"

namespace hinf::synth {

// What a sweep varies (docs/maths.md §21). A named parameter of the config (`parameters:`,
// §22) is its design point in its own units: the nominal becomes the value and the range moves
// with it. `delta_bar` names hill.delta_bar; `uncertainty_scale` multiplies the uncertainty's E
// (1 = the config as written: for a plant whose E carries the bound δ̄, the value scales δ̄);
// any other name is a key path of the config holding a plain number ("hill.sample_time",
// "solver.backoff"). A named parameter wins over the two words.
struct SweepParameter {
  enum class Kind { KeyPath, UncertaintyScale, NamedParameter };
  std::string name;      // as the user wrote it
  std::string key_path;  // the config key it replaces (Kind::KeyPath)
  Kind kind = Kind::KeyPath;
};
// Error InvalidInput naming the parameter if the config has no such number.
SweepParameter resolve_sweep_parameter(const std::string& name, const std::string& yaml_text,
                                       const std::string& source_name);

// The config with the parameter at `value` (parsed and validated as `solve` reads it).
SynthConfig config_at(const SweepParameter& parameter, double value, const std::string& yaml_text,
                      const std::string& source_name);

struct SweepPoint {
  double value = 0;
  ErrorCode outcome = ErrorCode::Ok;  // what `solve` would exit with: Ok, Infeasible, NumericalFailure, InvalidInput
  double gamma = 0;                   // the certified bound (outcome Ok)
  bool gap_certified = false;         // outcome Ok: γ* ≥ gamma_lower is verified (docs/maths.md §5.9)
  double gamma_lower = 0;             // √ of the verified lower bound on γ*² (gap_certified)
  std::string form;                   // "augmented" | "observer" (outcome Ok)
  std::string message;                // the error's message (outcome not Ok)
  double time_s = 0;
};

// The word for a point's outcome in the CSV, the JSON and Python: certified, infeasible,
// numerical_failure, invalid_input, check_failed.
const char* sweep_outcome_word(ErrorCode outcome);

// `synthesize` at each value, in order. A point's failure to solve is recorded, never
// thrown; a value that makes the config invalid is Error InvalidInput before any solve.
// `interrupted`: the solver's poll (sdp::Options::interrupted); once true, every point left
// ends at once as a numerical failure "… interrupted". `on_point`: called with each point as
// it ends (a front end's progress).
using SweepPointObserver = std::function<void(const SweepPoint&)>;
std::vector<SweepPoint> sweep(const SweepParameter& parameter, const std::vector<double>& values,
                              const std::string& yaml_text, const std::string& source_name,
                              const std::function<bool()>& interrupted = nullptr,
                              const SweepPointObserver& on_point = nullptr);

// lo:step:hi as the user writes it (step > 0, lo ≤ hi; hi included to a rounding of step);
// Error InvalidInput naming `option` otherwise. At most kMaxSweepPoints values.
inline constexpr int kMaxSweepPoints = 10000;
std::vector<double> parse_sweep_range(const std::string& text, const std::string& option);

// The largest value in [lo, hi] with a certified filter, by bisection (docs/maths.md §21).
// Certified at `lo` is required (else Error Infeasible / NumericalFailure with lo's
// message); if `hi` is certified too the answer is hi (`bracketed` false). Otherwise the
// bisection keeps [certified, not certified] until the width is at most `tolerance`; if
// the upper end failed numerically and a larger value was verified infeasible, the values
// between are bisected on "verified infeasible" to the same tolerance.
struct FeasibilitySearch {
  SweepPoint largest_certified;
  std::optional<SweepPoint> smallest_not_certified;  // where the bracket's upper end failed
  std::optional<SweepPoint> smallest_infeasible;     // the smallest value verified infeasible (exit 3)
  bool bracketed = false;                            // hi not certified: the bracket below is the answer
  double width = 0;                                  // smallest_not_certified − largest_certified
  std::vector<SweepPoint> evaluated;                 // every solve, in the order run
};
FeasibilitySearch max_feasible(const SweepParameter& parameter, double lo, double hi, double tolerance,
                               const std::string& yaml_text, const std::string& source_name,
                               const std::function<bool()>& interrupted = nullptr,
                               const SweepPointObserver& on_point = nullptr);

}  // namespace hinf::synth
