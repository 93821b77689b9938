// Analysis of any given filter against a plant (hinf-synth analyze).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "hinf/synth/hill_plant.hpp"
#include "hinf/synth/parametric_uncertainty.hpp"
#include "hinf/synth/synthesis.hpp"

namespace hinf::synth {

struct DeltaPoint {
  double delta = 0;          // ω = ω₀(1 + δ)
  double spectral_radius = 0;
  double hinf_norm = 0;      // +inf if the error system is unstable at this δ
};

struct FilterAnalysis {
  double spectral_radius_nominal = 0;
  double hinf_norm_nominal = 0;        // +inf if unstable
  double hinf_norm_peak_frequency = 0;
  double robust_bound = 0;             // analysis LMI (S-procedure); +inf if infeasible
  double spectral_radius_sampled_max = 0;  // over sampled full-block ‖F‖ ≤ 1
  // Uncertain plants: the worst constant admissible F found (certify/worst_case.hpp): the
  // error system's gain there, a lower value of the worst case that robust_bound bounds above
  bool has_worst_F = false;
  double worst_F_gain = 0;
  Eigen::MatrixXd worst_F;
  int worst_F_evaluations = 0;
  // Named parameters (§22): the worst case found over their own box, F = diag(δᵢ I) with every
  // pᵢ = νᵢ + δᵢ rᵢ in its range (certify::worst_case_gain_over_box), in the parameters' units
  struct ParameterValue {
    std::string name;
    double value = 0;
  };
  std::vector<ParameterValue> worst_parameters;  // empty: no named parameter enters A
  double worst_parameters_gain = 0;
  int worst_parameters_evaluations = 0;
  // Hill model only: exact plant at frozen δ on a grid over [−δ̄, δ̄] (structured F)
  std::vector<DeltaPoint> delta_grid;
  double worst_delta = 0, worst_delta_hinf_norm = 0;
};

FilterAnalysis analyze_filter(const Plant& plant, const std::optional<HillPlantSpec>& hill,
                              const std::vector<ParameterBlock>& parameters, const Filter& filter,
                              const Settings& settings, int delta_points = 41);

}  // namespace hinf::synth
