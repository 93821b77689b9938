// What the controller kind's jobs report (controller_problem.cpp): the text a front end
// prints and the jobs' JSON, formatted from the results; no maths, no reading.
#pragma once
#include <optional>
#include <string>

#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/controller_regression.hpp"
#include "hinf/synth/sampled_loop.hpp"

namespace hinf::synth::controller_report {

std::string solve(const ControllerSynthesisResult& r, const ControllerConfig& cfg);
// `claimed_gamma`: the file's γ, if it states one.
std::string analysis(const std::string& controller_path, std::optional<double> claimed_gamma,
                     const ControllerCertificate& c, bool discrete);
// The jobs' JSON (job_json.hpp): `config_path` the config's source name; `disk`: the design
// asks for a pole disk.
std::string analysis_json(const std::string& config_path, const std::string& controller_path,
                          std::optional<double> claimed_gamma, const ControllerCertificate& c);
std::string verification(double claimed_gamma, const ControllerVerification& v, bool discrete);
std::string check(double golden_gamma, const std::string& golden_sha256, const std::string& config_sha256,
                  double gamma_now, const ControllerGoldenComparison& cmp, double rtol);
std::string verification_json(const std::string& config_path, const std::string& controller_path,
                              double claimed_gamma, const ControllerVerification& v, bool discrete, bool disk);
std::string check_json(const std::string& config_path, const std::string& golden_path, double golden_gamma,
                       const std::string& golden_sha256, const std::string& config_sha256, double gamma_now,
                       const ControllerGoldenComparison& cmp, double rtol, bool discrete, bool disk);

// codegen --tustin/--zoh: the sampled loop's certificate (docs/maths.md (161b)), `continuous_gamma`
// the continuous file's γ; when it does not hold, says what failed.
std::string discretised(const std::string& controller_path, double period, ControllerSampling method,
                        std::optional<double> continuous_gamma, bool holds, const ControllerCertificate& c);
std::string discretised_json(const std::string& config_path, const std::string& controller_path, double period,
                             ControllerSampling method, std::optional<double> continuous_gamma, bool holds,
                             const ControllerCertificate& c);

}  // namespace hinf::synth::controller_report
