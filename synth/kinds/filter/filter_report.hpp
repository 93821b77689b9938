// What the filter kind's jobs report (filter_problem.cpp): the text a front end prints and
// the jobs' JSON, formatted from the results; no maths, no reading.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/synth/analysis.hpp"
#include "hinf/synth/regression.hpp"
#include "hinf/synth/synthesis.hpp"

namespace hinf::synth::filter_report {

using LogLine = std::function<void(const std::string&)>;

// Before a solve (--verbose): the coefficient ranges of the plant's matrices (docs/maths.md
// [D5]) and the problem's size, memory and time estimates.
void log_before_solve(const Plant& plant, const Settings& settings, const LogLine& log);
// After it: the scaling applied and the optimality gap.
void log_after_solve(const SolverInfo& solver, const LogLine& log);

std::string solve(const SynthesisResult& r);
std::string kalman(const SynthesisResult& r);
std::string analysis(const std::string& gains_path, const runtime_yaml::GainsFile& g, const FilterAnalysis& a,
                     std::optional<double> sample_time, bool uncertain);
// The jobs' JSON (job_json.hpp): `config_path` the config's source name.
std::string analysis_json(const std::string& config_path, const std::string& gains_path,
                          const runtime_yaml::GainsFile& g, const FilterAnalysis& a, std::optional<double> sample_time);
std::string verification(const Filter& f, double claimed_gamma, const Verification& v);
std::string check(const runtime_yaml::GainsFile& golden, const std::string& config_sha256, double gamma_now,
                  const GoldenComparison& cmp, double rtol);
std::string verification_json(const std::string& config_path, const std::string& gains_path, const Filter& f,
                              double claimed_gamma, const Verification& v);
std::string check_json(const std::string& config_path, const std::string& golden_path, const runtime_yaml::GainsFile& golden,
                       const Filter& golden_filter, const std::string& config_sha256, double gamma_now,
                       const GoldenComparison& cmp, double rtol);

}  // namespace hinf::synth::filter_report
