// Admissible ranges of the solver settings (settings.hpp). Each message names the field
// (as a config's `solver:` section spells it) and the offending value.
#include <cmath>
#include <string>

#include "hinf/common/number_text.hpp"
#include "hinf/synth/settings.hpp"
#include "hinf/common/error.hpp"

namespace hinf::synth {
namespace {

// Below this the strictness margin is lost in the rounding of the Cholesky test of
// −M(x) − εI (M of order ~1 after equilibration): a "strict" LMI would silently become
// non-strict (docs/maths.md [D3]).
constexpr double kSolverTolerance = 1e-14;

// Names the Settings field; the config reader re-keys it to "solver.<field>".
[[noreturn]] void fail(const char* field, const std::string& value, const std::string& why) {
  throw Error::invalid_field(field, " = " + value + ": " + why);
}

void require_finite(const char* field, double v) {
  if (!std::isfinite(v)) fail(field, number_text(v), "must be finite");
}

}  // namespace

void Settings::validate() const {
  require_finite("lmi_margin", solver.lmi_margin);
  if (!(solver.lmi_margin > 0)) fail("lmi_margin", number_text(solver.lmi_margin), "must be > 0");
  if (solver.lmi_margin < kSolverTolerance)
    fail("lmi_margin", number_text(solver.lmi_margin),
         "below solver tolerance (must be >= " + number_text(kSolverTolerance) +
             ", or the strict LMI is not enforced)");
  if (solver.lmi_margin > 1e-2) fail("lmi_margin", number_text(solver.lmi_margin), "must be <= 0.01");

  require_finite("relative_gap_tol", solver.relative_gap_tol);
  if (solver.relative_gap_tol < 1e-12 || solver.relative_gap_tol > 1e-2)
    fail("relative_gap_tol", number_text(solver.relative_gap_tol), "must be in [1e-12, 0.01]");

  require_finite("barrier_growth", solver.barrier_growth);
  if (!(solver.barrier_growth > 1.5)) fail("barrier_growth", number_text(solver.barrier_growth), "must be > 1.5");
  if (solver.barrier_growth > 1e6) fail("barrier_growth", number_text(solver.barrier_growth), "must be <= 1e6");

  require_finite("feasibility_radius", solver.feasibility_radius);
  if (solver.feasibility_radius < 1 || solver.feasibility_radius > 1e15)
    fail("feasibility_radius", number_text(solver.feasibility_radius), "must be in [1, 1e15]");

  if (solver.max_newton_per_centering < 1 || solver.max_newton_per_centering > 10000)
    fail("max_newton_per_centering", std::to_string(solver.max_newton_per_centering),
         "must be in [1, 10000]");
  if (solver.max_iterations < 1 || solver.max_iterations > 1000000)
    fail("max_iterations", std::to_string(solver.max_iterations), "must be in [1, 1000000]");

  require_finite("max_memory_mb", max_memory_mb);
  if (max_memory_mb < 64 || max_memory_mb > 1048576)
    fail("max_memory_mb", number_text(max_memory_mb), "must be in [64, 1048576] (MiB)");

  require_finite("time_limit_s", solver.time_limit_s);
  if (!(solver.time_limit_s > 0)) fail("time_limit_s", number_text(solver.time_limit_s), "must be > 0");

  require_finite("gamma_backoff", gamma_backoff);
  if (gamma_backoff < 0 || gamma_backoff > 1)
    fail("gamma_backoff", number_text(gamma_backoff),
         "must be in [0, 1] (0 = off; 0.01 means gamma = 1.01 gamma*)");

  if (stability_samples < 0 || stability_samples > 1000000)
    fail("stability_samples", std::to_string(stability_samples), "must be in [0, 1000000]");
  // seed: every unsigned value is admissible; verbose: a bool.
}

}  // namespace hinf::synth
