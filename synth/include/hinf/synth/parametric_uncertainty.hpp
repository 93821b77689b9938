// Named uncertain parameters (docs/maths.md §22): A(p) = A₀ + Σᵢ (pᵢ − νᵢ) Aᵢ with each pᵢ
// in [loᵢ, hiᵢ], written by the tool as the norm-bounded ΔA = H F E of (4).
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace hinf::synth {

struct UncertainParameter {
  std::string name;
  double nominal = 0;  // ν: the plant the filter is designed about (A₀ = A(ν))
  double low = 0;      // the parameter's range [low, high], low ≤ ν ≤ high, low < high
  double high = 0;
  // r = max(high − ν, ν − low): |p − ν| ≤ r covers the range ((137); exact when ν is its centre)
  double radius() const;
};

// A parameter that enters A and its place in F = diag(δ₁ I_{s₁}, …): its s columns of H,
// in the order of the parameters (docs/maths.md (138)).
struct ParameterBlock {
  UncertainParameter parameter;
  int columns = 0;
  // δ = (p − ν)/r ↔ p; the range [low, high] is δ ∈ [(low − ν)/r, (high − ν)/r] ⊆ [−1, 1] (137)
  double value_at(double delta) const { return parameter.nominal + delta * parameter.radius(); }
  double delta_of(double value) const { return (value - parameter.nominal) / parameter.radius(); }
};

// H, E with F = diag(δᵢ I) (δᵢ = (pᵢ − νᵢ)/rᵢ ∈ [−1, 1]) inside the full block ‖F‖ ≤ 1: per
// parameter, Aᵢ = Aᵢ[:, P] X with P the columns of Aᵢ that are not combinations of the
// columns before them (a column skeleton), giving H's columns Aᵢ[:, P] and E's rows rᵢ X
// (docs/maths.md (138)). `coefficients[i]` is Aᵢ (the shape of A, n rows). A parameter
// that enters no entry adds nothing.
struct UncertaintyFactors {
  Eigen::MatrixXd H;  // n×j
  Eigen::MatrixXd E;  // j×n
  std::vector<int> blocks;  // F's block per parameter (Plant::F_blocks); empty when one parameter enters
  std::vector<ParameterBlock> parameter_blocks;  // the parameters that enter, with their columns
};
UncertaintyFactors uncertainty_from_parameters(const std::vector<Eigen::MatrixXd>& coefficients,
                                               const std::vector<UncertainParameter>& parameters, Eigen::Index n);

}  // namespace hinf::synth
