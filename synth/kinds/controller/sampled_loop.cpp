// sample_controller, sample_generalised_plant, sample_channel (sampled_loop.hpp).
#include "hinf/synth/sampled_loop.hpp"

#include <cmath>
#include <string>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/models/discretise.hpp"

namespace hinf::synth {

void require_sample_period(double T, const std::string& key) {
  if (!(std::isfinite(T) && T > 0))
    throw Error(ErrorCode::InvalidInput, key + " = " + number_text(T) + ": must be a positive, finite period (s)", key);
}

Controller sample_controller(const Controller& K, double T, ControllerSampling method) {
  if (method == ControllerSampling::Tustin) return tustin(K, T);
  const models::SampledMatrices s = models::discretise(K.A_K, T, models::Discretisation::ZeroOrderHold);
  return {s.A, s.Gamma * K.B_K, K.C_K, K.D_K};
}

GeneralisedPlant sample_generalised_plant(const GeneralisedPlant& P, double T, const char* period_key) {
  const std::string stiff = models::held_input_problem(P.A, T);
  if (!stiff.empty()) throw Error(ErrorCode::InvalidInput, std::string(period_key) + ": " + stiff, period_key);
  const models::SampledMatrices s = models::discretise(P.A, T, models::Discretisation::ZeroOrderHold);
  GeneralisedPlant d = P;
  d.time = TimeDomain::Discrete;
  d.sample_time = T;
  d.A = s.A;
  d.B1 = s.Gamma * P.B1;
  d.B2 = s.Gamma * P.B2;
  if (!d.A.allFinite() || !d.B1.allFinite() || !d.B2.allFinite())
    throw Error(ErrorCode::InvalidInput, std::string(period_key) + ": the plant sampled at this period is not finite",
                period_key);
  return d;
}

UncertaintyChannel sample_channel(const GeneralisedPlant& P, const UncertaintyChannel& channel, double T) {
  const models::SampledMatrices s = models::discretise(P.A, T, models::Discretisation::ZeroOrderHold);
  return {s.Gamma * channel.H, channel.E};
}

}  // namespace hinf::synth
