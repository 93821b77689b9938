// Parameter studies of a config: sweep and bisection for the largest certified value
// (docs/maths.md §21).
#include "hinf/synth/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>

#include "hinf/common/number_text.hpp"
#include "hinf/common/suggest.hpp"
#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/synthesis.hpp"
#include "bisection.hpp"

namespace hinf::synth {
namespace {

constexpr const char* kUncertaintyScale = "uncertainty_scale";
constexpr const char* kDeltaBar = "delta_bar";

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// `solve` at one value: its outcome, never thrown.
SweepPoint solve_at(const SweepParameter& parameter, double value, const std::string& yaml_text,
                    const std::string& source_name, const std::function<bool()>& interrupted) {
  SweepPoint point;
  point.value = value;
  const auto start = std::chrono::steady_clock::now();
  try {
    SynthConfig cfg = config_at(parameter, value, yaml_text, source_name);
    cfg.settings.solver.interrupted = interrupted;
    const SynthesisResult r = synthesize(cfg.plant, cfg.settings);
    point.gamma = r.gamma;
    point.form = to_string(r.filter.form);
    point.gap_certified = r.solver.gap_certified;
    if (r.solver.gap_certified) point.gamma_lower = std::sqrt(r.solver.dual_bound_gamma_squared);
  } catch (const Error& e) {
    point.outcome = e.code();
    point.message = e.what();
  }
  point.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return point;
}

}  // namespace

SweepParameter resolve_sweep_parameter(const std::string& name, const std::string& yaml_text,
                                       const std::string& source_name) {
  if (declares_controller(yaml_text))
    throw Error(ErrorCode::InvalidInput,
                source_name + " declares a controller (controller:); a sweep studies a filter config's certified "
                              "gamma (system: or hill:)",
                "controller");
  SweepParameter p{name, name};
  const std::vector<std::string> parameters = parameter_names(yaml_text, source_name);
  if (std::find(parameters.begin(), parameters.end(), name) != parameters.end()) {
    p.kind = SweepParameter::Kind::NamedParameter;
    p.key_path.clear();
    with_parameter_value(yaml_text, source_name, name, 0);  // names the key if its numbers are not plain
    return p;
  }
  if (name == kUncertaintyScale) {
    p.kind = SweepParameter::Kind::UncertaintyScale;
    p.key_path.clear();
    const SynthConfig cfg = parse_config(yaml_text, source_name);
    if (cfg.plant.E.rows() == 0)
      throw Error(ErrorCode::InvalidInput, source_name + ": uncertainty_scale: the plant has no uncertainty (E has no "
                                                         "rows), so there is nothing to scale",
                  name);
    return p;
  }
  if (name == kDeltaBar) p.key_path = "hill.delta_bar";
  try {
    with_value(yaml_text, source_name, p.key_path, 0);  // names the key if it is not a number of the config
  } catch (const Error&) {
    if (parameters.empty() || name.find('.') != std::string::npos) throw;
    const auto near = closest_match(name, parameters);
    throw Error(ErrorCode::InvalidInput,
                source_name + ": '" + name + "' is neither a parameter of the config (" +
                    (near ? "did you mean '" + *near + "'?" : "its parameters: " + join(parameters)) +
                    ") nor a key holding a number",
                name);
  }
  return p;
}

SynthConfig config_at(const SweepParameter& parameter, double value, const std::string& yaml_text,
                      const std::string& source_name) {
  if (!std::isfinite(value))
    throw Error(ErrorCode::InvalidInput, parameter.name + " = " + number_text(value) + ": not finite", parameter.name);
  const std::string at = source_name + " with " + parameter.name + " = " + number_text(value);
  if (parameter.kind == SweepParameter::Kind::KeyPath)
    return parse_config(with_value(yaml_text, source_name, parameter.key_path, value), at);
  if (parameter.kind == SweepParameter::Kind::NamedParameter)
    return parse_config(with_parameter_value(yaml_text, source_name, parameter.name, value), at);
  if (value < 0)
    throw Error(ErrorCode::InvalidInput, parameter.name + " = " + number_text(value) + ": must be >= 0", parameter.name);
  SynthConfig cfg = parse_config(yaml_text, at);
  cfg.plant.E *= value;  // E is the same in continuous and discrete time (docs/maths.md (129))
  return cfg;
}

std::vector<SweepPoint> sweep(const SweepParameter& parameter, const std::vector<double>& values,
                              const std::string& yaml_text, const std::string& source_name,
                              const std::function<bool()>& interrupted, const SweepPointObserver& on_point) {
  for (double v : values) config_at(parameter, v, yaml_text, source_name);  // every value valid before any solve
  std::vector<SweepPoint> points;
  points.reserve(values.size());
  for (double v : values) {
    points.push_back(solve_at(parameter, v, yaml_text, source_name, interrupted));
    if (on_point) on_point(points.back());
  }
  return points;
}

const char* sweep_outcome_word(ErrorCode outcome) {
  switch (outcome) {
    case ErrorCode::Ok: return "certified";
    case ErrorCode::Infeasible: return "infeasible";
    case ErrorCode::NumericalFailure: return "numerical_failure";
    case ErrorCode::InvalidInput: return "invalid_input";
    case ErrorCode::CheckFailed: return "check_failed";
  }
  return "unknown";
}

std::vector<double> parse_sweep_range(const std::string& text, const std::string& option) {
  const auto fail = [&](const std::string& why) -> Error {
    return Error(ErrorCode::InvalidInput, option + " '" + text + "': " + why, option);
  };
  std::vector<double> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t colon = text.find(':', start);
    const std::string part = text.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(part, &used);
    } catch (const std::exception&) {
      throw fail("'" + part + "' is not a number (expected LO:STEP:HI, e.g. 0:0.05:1)");
    }
    if (used != part.size() || !std::isfinite(v) || !is_decimal_number(part))
      throw fail("'" + part + "' is not a finite decimal number");
    parts.push_back(v);
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts.size() == 1) return parts;
  if (parts.size() != 3) throw fail("expected LO:STEP:HI (three numbers) or one value");
  const double lo = parts[0], step = parts[1], hi = parts[2];
  if (!(step > 0)) throw fail("STEP must be > 0");
  if (hi < lo) throw fail("HI must be >= LO");
  const double count = std::floor((hi - lo) / step + 1e-9) + 1;
  if (count > kMaxSweepPoints) throw fail("more than " + std::to_string(kMaxSweepPoints) + " points");
  std::vector<double> values;
  for (int i = 0; i < static_cast<int>(count); ++i) values.push_back(lo + i * step);  // no accumulated rounding
  return values;
}

FeasibilitySearch max_feasible(const SweepParameter& parameter, double lo, double hi, double tolerance,
                               const std::string& yaml_text, const std::string& source_name,
                               const std::function<bool()>& interrupted, const SweepPointObserver& on_point) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw Error(ErrorCode::InvalidInput, "--tolerance = " + number_text(tolerance) + ": must be > 0", "tolerance");
  if (!(lo < hi)) throw Error(ErrorCode::InvalidInput, "--max-feasible: LO must be < HI", parameter.name);
  for (double v : {lo, hi}) config_at(parameter, v, yaml_text, source_name);  // both ends valid before any solve
  FeasibilitySearch s;
  const auto run = [&](double v) {
    s.evaluated.push_back(solve_at(parameter, v, yaml_text, source_name, interrupted));
    const SweepPoint& p = s.evaluated.back();
    if (on_point) on_point(p);
    if (p.outcome == ErrorCode::InvalidInput) throw Error(ErrorCode::InvalidInput, p.message, parameter.name);
    if (p.outcome == ErrorCode::Infeasible && (!s.smallest_infeasible || v < s.smallest_infeasible->value))
      s.smallest_infeasible = p;
    return p;
  };
  const SweepPoint low = run(lo);
  if (low.outcome != ErrorCode::Ok)
    throw Error(low.outcome, "--max-feasible: no certified filter at the lower end " + parameter.name + " = " +
                                 number_text(lo) + ": " + low.message);
  s.largest_certified = low;
  const SweepPoint high = run(hi);
  if (high.outcome == ErrorCode::Ok) {
    s.largest_certified = high;
    return s;
  }
  s.bracketed = true;
  s.smallest_not_certified = high;
  // Invariant: certified at largest_certified, not at smallest_not_certified (§21).
  double certified = lo, not_certified = hi;
  bisect(certified, not_certified, tolerance, [&](double mid) {
    const SweepPoint p = run(mid);
    if (p.outcome == ErrorCode::Ok) s.largest_certified = p;
    else s.smallest_not_certified = p;
    return p.outcome == ErrorCode::Ok;
  });
  s.width = s.smallest_not_certified->value - s.largest_certified.value;
  // Above a numerical failure, the verified-infeasible side is bisected too (its verdicts
  // are cheap: the pre-flight's witness), so that [largest certified, smallest verified
  // infeasible] brackets the boundary with the band of no verdict named in between.
  if (s.smallest_infeasible && s.smallest_not_certified->outcome != ErrorCode::Infeasible) {
    double below = s.smallest_not_certified->value, infeasible = s.smallest_infeasible->value;
    bisect(below, infeasible, tolerance, [&](double mid) { return run(mid).outcome != ErrorCode::Infeasible; });
  }
  return s;
}

}  // namespace hinf::synth
