// What the controller kind's jobs report (controller_problem.cpp): the text a front end
// prints and analyze's JSON, formatted from the results; no maths, no reading.
#pragma once
#include <optional>
#include <string>

#include "hinf/synth/controller_config.hpp"
#include "hinf/synth/controller_regression.hpp"

namespace hinf::synth::controller_report {

std::string solve(const ControllerSynthesisResult& r, const ControllerConfig& cfg);
// `claimed_gamma`: the file's γ, if it states one.
std::string analysis(const std::string& controller_path, std::optional<double> claimed_gamma,
                     const ControllerCertificate& c, bool discrete);
std::string analysis_json(const std::string& controller_path, std::optional<double> claimed_gamma,
                          const ControllerCertificate& c);
std::string verification(double claimed_gamma, const ControllerVerification& v, bool discrete);
std::string check(double golden_gamma, const std::string& golden_sha256, const std::string& config_sha256,
                  double gamma_now, const ControllerGoldenComparison& cmp, double rtol);

}  // namespace hinf::synth::controller_report
