// Matrix entries written as affine expressions of named uncertain parameters
// (docs/file-formats.md "parameters", docs/maths.md §22): numbers, named constants and
// parameters combined by + − * / and parentheses, e.g. `-(k1 + k2)/m`, `3*w0*w0*(1 + s)`.
// A product or quotient must keep the result affine in the parameters (a parameter times
// a constant; never k1*k2, never 1/k1).
#pragma once
#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

namespace hinf::synth {

// The names an expression may use: constants (values) and parameters (indices 0..P-1).
struct ExpressionSymbols {
  std::map<std::string, double> constants;
  std::vector<std::string> parameters;
  bool empty() const { return constants.empty() && parameters.empty(); }
};

// c + Σᵢ aᵢ pᵢ.
struct AffineForm {
  double constant = 0;
  Eigen::VectorXd coefficients;  // one per parameter of the symbols
};

// Parses `text`; throws Error(InvalidInput) whose message says what is wrong at which
// character (an unknown name with a suggestion, a product of parameters, a division by
// zero, a non-finite value), without a location: the caller prefixes the entry's.
AffineForm parse_affine_expression(const std::string& text, const ExpressionSymbols& symbols);

}  // namespace hinf::synth
