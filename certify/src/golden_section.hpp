// Golden-section search for a local minimum of a function of one variable on [a, b]:
// the one implementation behind the H∞ norm's peak search (the minimum of −σ_max) and
// check 4's fallback search over log λ (the minimum of the scaled norm).
#pragma once

namespace hinf::certify::detail {

// 1/φ = (√5 − 1)/2: each step keeps this fraction of the bracket.
constexpr double kInvGoldenRatio = 0.6180339887498949;

// At most `max_steps` shrinks of [a, b]; before each, `done(a, b)` may end the search.
// Every trial value goes through f, so a caller that records the best point it saw keeps
// it whether or not f is unimodal. Ties keep the left part of the bracket.
template <class F, class Done>
void golden_section_minimise(F&& f, double a, double b, int max_steps, Done&& done) {
  double x1 = b - kInvGoldenRatio * (b - a), x2 = a + kInvGoldenRatio * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int step = 0; step < max_steps && !done(a, b); ++step) {
    if (f1 <= f2) {  // a minimum lies in [a, x2]
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - kInvGoldenRatio * (b - a);
      f1 = f(x1);
    } else {  // a minimum lies in [x1, b]
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + kInvGoldenRatio * (b - a);
      f2 = f(x2);
    }
  }
}

}  // namespace hinf::certify::detail
