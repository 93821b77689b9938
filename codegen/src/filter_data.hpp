// The numbers behind the generated code: coefficients rounded to the target real
// type, the offline pseudo-inverse for x_F(0) = C_F⁺ z0, and the test vectors.
// Maths only; printing is in emit_c.cpp.
#pragma once
#include <Eigen/Dense>
#include <cstdint>

#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/codegen/codegen.hpp"

namespace hinf::codegen::detail {

// Every entry is exactly representable in the target real type.
struct FilterData {
  Eigen::MatrixXd A_F, B_F, C_F;  // docs/maths.md (5)–(6)
  Eigen::MatrixXd D_F;            // l × m feedthrough of a filtered estimate (140); zero without
  bool feedthrough = false;       // the gains file has D_F (filter.estimate: filtered)
  Eigen::MatrixXd G_F;            // n × r known input (121); n × 0 without
  Eigen::MatrixXd C_F_pinv;       // Moore–Penrose pseudo-inverse of C_F (n × l)
};

// Throws Error(InvalidInput) if a coefficient overflows the real type.
FilterData make_filter_data(const runtime_yaml::GainsFile& gains, CodegenOptions::Real real);

struct TestVectors {
  Eigen::VectorXd z0;  // initial estimate passed to init (l)
  Eigen::MatrixXd y;   // inputs, row k = y(k) (N × m)
  Eigen::MatrixXd u;   // known inputs, row k = u(k) (N × r; N × 0 without)
  Eigen::MatrixXd z;   // expected outputs, row k = z(k) (N × l), rounded to the real type
  double tolerance;    // bound on |z_generated(k) − z(k)|, see make_test_vectors
};

// Inputs: splitmix64(seed) mapped to uniform [-1, 1), rounded to the real type: z0, then
// y(0..N-1), then u(0..N-1) (so a filter without a known input has the vectors it always had).
// Expected outputs: init + docs/maths.md (5)–(6) (with D_F y(k), (140), and G_F u(k), (121))
// evaluated in long double on the emitted data.
// Tolerance: an a-priori running rounding-error bound (Higham, "Accuracy and
// Stability of Numerical Algorithms", §3.1: |fl(aᵀb) − aᵀb| ≤ γ_k |a|ᵀ|b|,
// γ_k = k u / (1 − k u)) propagated through the recursion with |A_F|, for the target
// arithmetic plus the long-double reference, plus the rounding of the stored
// expected values. Throws Error(NumericalFailure) if the outputs overflow.
TestVectors make_test_vectors(const FilterData& data, CodegenOptions::Real real, int steps,
                              std::uint64_t seed);

}  // namespace hinf::codegen::detail
