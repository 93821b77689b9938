// The synthesis API (docs/design.md "The synthesis API"): one include for users, one entry
// per job — synthesise, analyse, verify, check against a golden file, export the LMI — over
// every problem kind. A config is parsed once into a `Problem`; the registry
// (synth/src/kind_registry.cpp) picks its kind from the config's keys, and each kind
// (synth/kinds/<name>/) supplies its LMI, recovery, certificate, file section and report
// behind this one interface. Nothing here prints, exits or writes a file: a job returns its
// result in memory — the typed result, the file's text, the report a front end prints — and
// failures are hinf::Error, whose code is the exit code (common/error.hpp).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "hinf/synth/analysis.hpp"
#include "hinf/synth/controller_regression.hpp"
#include "hinf/synth/controller_synthesis.hpp"
#include "hinf/synth/regression.hpp"
#include "hinf/synth/sampled_loop.hpp"
#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

// What a caller hears while a job runs, and how it stops one; each may be empty (the
// default: nothing).
struct JobObservers {
  // Every solver iteration (solve and check), for an iteration table.
  IterationObserver on_iteration;
  // The lines of the verbose account of a solve (coefficient ranges, problem size and time
  // estimate, the scaling applied, the optimality gap), one line per call, no newline.
  std::function<void(const std::string&)> on_log;
  // Polled by the solver (sdp::Options::interrupted, within one LMI term's work): true ends
  // the job soon with Error(NumericalFailure) "… interrupted" (a front end's Ctrl-C).
  std::function<bool()> interrupted;
};

// `solve`: the certified design.
struct SolveOutcome {
  double gamma = 0;
  std::string file;    // the file to write: hinf-gains/1 (filters) or hinf-controller/1 (controllers)
  std::string file_contents;  // what the file holds, for people: "gains", "controller"
  std::string report;  // the summary a front end prints (lines ending in '\n')
  // The same as one line of JSON (no newline): schema "hinf-synth.solve/1" (or ".kalman/1"),
  // kind, config, gamma, file_contents and the file itself under "file" (docs/file-formats.md).
  std::string json;
  std::variant<SynthesisResult, ControllerSynthesisResult> result;
};

struct AnalysisOptions {
  // Points of the δ grid over [−δ̄, δ̄] (configs with `hill:`), 2 to 100001.
  int delta_points = 41;
};

// `analyze`: the figures of a given gains or controller file on the problem (no verdict).
struct AnalysisOutcome {
  std::string report;  // text
  std::string json;    // the same figures as one line of JSON (no newline), schema "hinf-synth.analyze/1"
  std::variant<FilterAnalysis, ControllerCertificate> result;
};

// `verify`: whether the file's claimed γ holds for the problem (the certificate re-derived).
struct VerifyOutcome {
  bool holds = false;
  std::string report;
  std::string json;  // one line, schema "hinf-synth.verify/1": holds, the claimed γ, checks 2–4
  std::variant<Verification, ControllerVerification> result;
};

// `check`: the problem synthesised again and compared with a golden file.
struct CheckOutcome {
  bool same = false;
  double gamma_now = 0;
  std::string report;
  std::string json;  // one line, schema "hinf-synth.check/1"
  std::variant<GoldenComparison, ControllerGoldenComparison> result;
};

// `codegen --tustin T` / `--zoh T`: a continuous-time controller file flown at period T, its
// sampled loop certified on the config's plant sampled at T (docs/maths.md (161a)–(161c)).
struct DiscretiseOutcome {
  bool holds = false;  // the sampled loop is stable (and robustly stable with a channel)
  double gamma = 0;    // when it holds: the sampled loop's certified ℓ2 gain from w to z
  // When it holds: the discrete controller file (hinf-controller/1, `discretised:` section)
  // with that γ; empty otherwise.
  std::string file;
  std::string report;  // text; when it does not hold, says what failed
  std::string json;    // one line, schema "hinf-synth.discretise/1"
  ControllerCertificate certificate;
};

// A parsed, validated config of one problem kind. Jobs are const and may run concurrently.
class Problem {
 public:
  virtual ~Problem() = default;
  // The kind's registered name ("filter", "controller").
  virtual std::string_view kind() const = 0;
  // The path (or source name) the config was read from, and the SHA-256 of its bytes.
  virtual const std::string& source() const = 0;
  virtual const std::string& sha256() const = 0;
  // True if the config itself asks for the verbose account (`solver: {verbose: true}`).
  virtual bool verbose() const = 0;

  virtual SolveOutcome solve(const JobObservers& observers = {}) const = 0;
  // `file_path`: a gains file (filters) or a controller file (controllers), read here.
  virtual AnalysisOutcome analyze(const std::string& file_path, const AnalysisOptions& options = {}) const = 0;
  virtual VerifyOutcome verify(const std::string& file_path) const = 0;
  // rtol: relative tolerance on γ and on the transfer functions' difference.
  virtual CheckOutcome check(const std::string& golden_path, double rtol, const JobObservers& observers = {}) const = 0;
  // The synthesis LMI in SDPA sparse format (for CSDP, SDPA, …), with provenance comments.
  virtual std::string export_sdpa() const = 0;
  // `kalman`: the Kalman one-step predictor of the nominal plant (the Kalman filter x̂(k|k)
  // for a filtered estimate; the config's `kalman: {Q, R}` or B Bᵀ, D Dᵀ), certified at the
  // worst-case gain it achieves — the H2 reference beside the H∞ design, as a gains file.
  // Error(InvalidInput) for a kind without one (a controller config).
  virtual SolveOutcome kalman() const = 0;
  // `codegen --tustin/--zoh`: the continuous-time controller file at `controller_path`
  // (synthesised from this config: its config_sha256 must be this config's) discretised at
  // `period` by `method` and its sampled loop certified (DiscretiseOutcome). Error(InvalidInput)
  // naming the period, the file, or a kind without controllers (a filter config).
  virtual DiscretiseOutcome discretise(const std::string& controller_path, double period,
                                       ControllerSampling method) const = 0;
};

// The `schema` key of a job's JSON, "hinf-synth.<job>/1" (docs/file-formats.md "JSON"): the
// outcomes' `json` above, and the JSON the front ends write of what they wrote (export-sdpa,
// codegen) and of the library calls without an outcome (compare, sweep).
std::string json_schema(std::string_view job);

// Parses config text of any kind; `source_name` names it in messages and in the outputs'
// provenance. Error(InvalidInput) naming the key, dimension or value.
std::unique_ptr<Problem> parse_problem(const std::string& yaml_text, const std::string& source_name);
// The same from a file's exact bytes (size-capped, regular files only).
std::unique_ptr<Problem> load_problem(const std::string& path);

// `codegen … --tustin T | --zoh T --config CONFIG`: the discretise job of the config at
// `config_path` on the controller file at `controller_path` (Problem::discretise); nullopt
// when neither period is given. Error(InvalidInput) naming --config when a period comes
// without it or it comes without a period, naming both periods when both are given.
std::optional<DiscretiseOutcome> discretise_for_codegen(const std::string& controller_path,
                                                        const std::string& config_path, std::optional<double> tustin,
                                                        std::optional<double> zoh);

}  // namespace hinf::synth
