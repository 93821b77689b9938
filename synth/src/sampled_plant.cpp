// Sampling of a continuous-time plant (docs/maths.md §19); see sampled_plant.hpp.
#include "hinf/synth/sampled_plant.hpp"

#include <cmath>
#include <limits>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"

namespace hinf::synth {

using Eigen::MatrixXd;

namespace {

// Finite and within validate_plant's 1e150 (whose squares the synthesis forms).
bool representable(const MatrixXd& M) { return M.allFinite() && (M.size() == 0 || M.cwiseAbs().maxCoeff() <= 1e150); }

}  // namespace

Plant sample_plant(const Plant& c, const SamplingSpec& spec) {
  const double T = spec.sample_time;
  if (!(T > 0) || !std::isfinite(T))
    throw Error::invalid_field("sample_time", " = " + number_text(T) + ": must be finite and > 0 (s)");
  if (spec.method == models::Discretisation::ZeroOrderHold || spec.white_process_noise)
    if (const std::string problem = models::held_input_problem(c.A, T); !problem.empty())
      throw Error::invalid_field("sample_time", " = " + number_text(T) + ": " + problem);
  const models::SampledMatrices s = models::discretise(c.A, T, spec.method);
  Plant d = c;
  d.A = s.A;
  d.B = spec.white_process_noise ? models::covariance_factor(models::sampled_white_noise_covariance(c.A, c.B, T))
                                 : MatrixXd(s.Gamma * c.B);
  d.G = c.G.size() > 0 ? MatrixXd(s.Gamma * c.G) : MatrixXd::Zero(c.n(), 0);
  if (c.uncertain()) {
    d.H = s.Gamma * c.H;
    if (spec.method == models::Discretisation::Tustin)
      d.E = c.E * (MatrixXd::Identity(c.n(), c.n()) + s.A) / 2;
  }
  if (!representable(d.A) || !representable(d.B) || !representable(d.G) || !representable(d.H) ||
      !representable(d.E))
    throw Error::invalid_field("sample_time", " = " + number_text(T) + ": the sampled plant (" +
                                                  models::to_string(spec.method) +
                                                  ") is not finite or beyond 1e150; the sample time is too long for A");
  if (d.B.cols() == 0)
    throw Error::invalid_field("B", ": the sampled white-noise covariance is zero, so the state is never excited");
  return d;
}

}  // namespace hinf::synth
