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
}  // namespace

FilterAnalysis analyze_filter(const Plant& plant, const std::optional<HillPlantSpec>& hill,
                              const Filter& filter, const Settings& settings, int delta_points) {
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
