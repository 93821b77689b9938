#include <cmath>

#include "hinf/synth/validate_plant.hpp"
#include "hinf/synth/analysis.hpp"
#include "hinf/certify/error_system.hpp"
#include "hinf/certify/hinf_norm.hpp"
#include "hinf/certify/stability.hpp"
#include "hinf/certify/worst_case.hpp"

namespace hinf::synth {

namespace {
// ‖error system‖∞, +inf when unstable.
double norm_or_inf(const StateSpace& es, double rho, double* peak = nullptr) {
  if (!(rho < 1)) return INFINITY;
  const certify::HinfNorm h = certify::discrete_hinf_norm(es, 1e-10);
  if (peak) *peak = h.peak_frequency;
  return h.norm;
}

// The worst case over the named parameters' own box (docs/maths.md §24): δᵢ over
// [(loᵢ − νᵢ)/rᵢ, (hiᵢ − νᵢ)/rᵢ], reported as the parameters' values.
void add_worst_parameters(FilterAnalysis& a, const Plant& plant, const std::vector<ParameterBlock>& parameters,
                          const Filter& filter, const Settings& settings) {
  const auto K = static_cast<Eigen::Index>(parameters.size());
  Eigen::VectorXd lower(K), upper(K);
  std::vector<int> sizes;
  for (Eigen::Index i = 0; i < K; ++i) {
    const ParameterBlock& p = parameters[static_cast<std::size_t>(i)];
    lower(i) = p.delta_of(p.parameter.low);
    upper(i) = p.delta_of(p.parameter.high);
    sizes.push_back(p.columns);
  }
  const certify::WorstCaseOverBox w =
      certify::worst_case_gain_over_box(plant, filter, sizes, lower, upper, settings.stability_samples);
  for (Eigen::Index i = 0; i < K; ++i) {
    const ParameterBlock& p = parameters[static_cast<std::size_t>(i)];
    a.worst_parameters.push_back({p.parameter.name, p.value_at(w.delta(i))});
  }
  a.worst_parameters_gain = w.gain;
  a.worst_parameters_evaluations = w.evaluations;
}

}  // namespace

FilterAnalysis analyze_filter(const Plant& plant, const std::optional<HillPlantSpec>& hill,
                              const std::vector<ParameterBlock>& parameters, const Filter& filter,
                              const Settings& settings, int delta_points) {
  validate_plant(plant);
  FilterAnalysis a;
  const StateSpace es = certify::error_system(plant, filter);
  a.spectral_radius_nominal = certify::spectral_radius(es.A);
  a.hinf_norm_nominal = norm_or_inf(es, a.spectral_radius_nominal, &a.hinf_norm_peak_frequency);
  a.spectral_radius_sampled_max =
      certify::sampled_robust_stability(plant, filter, settings.stability_samples, settings.seed).max_spectral_radius;
  if (a.spectral_radius_sampled_max < 1) {
    try {
      a.robust_bound = robust_bound(plant, filter, settings);
    } catch (const Error& e) {
      if (e.code() != ErrorCode::Infeasible) throw;
      a.robust_bound = INFINITY;
    }
  } else {
    a.robust_bound = INFINITY;
  }
  if (plant.uncertain()) {
    const certify::WorstCaseGain w = certify::worst_case_gain(plant, filter, settings.stability_samples, settings.seed);
    a.has_worst_F = true;
    a.worst_F_gain = w.gain;
    a.worst_F = w.worst_F;
    a.worst_F_evaluations = w.evaluations;
  }
  if (!parameters.empty()) add_worst_parameters(a, plant, parameters, filter, settings);
  if (hill && hill->delta_bar > 0 && delta_points >= 2) {
    for (int i = 0; i < delta_points; ++i) {
      DeltaPoint d;
      d.delta = hill->delta_bar * (-1.0 + 2.0 * i / (delta_points - 1));
      Plant pd = plant;
      pd.A = hill_exact_discrete_A(*hill, d.delta);  // the exact plant at this δ
      pd.H.resize(plant.n(), 0);
      pd.E.resize(0, plant.n());
      pd.F_blocks.clear();
      const StateSpace esd = certify::error_system(pd, filter);
      d.spectral_radius = certify::spectral_radius(esd.A);
      d.hinf_norm = norm_or_inf(esd, d.spectral_radius);
      if (i == 0 || d.hinf_norm > a.worst_delta_hinf_norm) {
        a.worst_delta = d.delta;
        a.worst_delta_hinf_norm = d.hinf_norm;
      }
      a.delta_grid.push_back(d);
    }
  }
  return a;
}

}  // namespace hinf::synth
