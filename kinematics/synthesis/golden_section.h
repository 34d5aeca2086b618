#pragma once
// Golden-section search for the maximum of a function of one variable on [lo, hi]: each step
// keeps the sub-interval holding the larger of two interior values, shrinking the bracket by
// 0.618. It needs no derivative, so it suits the synthesis objectives that are a minimum of
// two smooth pieces (the worst transmission angle) or an absolute value (a structural error's
// peak). On a unimodal function it converges to the maximum; callers bracket it first by
// sampling. Stops when the bracket is within `tolerance` (same unit as the variable).

#include <cmath>
#include <utility>

namespace linkwright::kinematics {

/// The argument of the maximum of `f` on [lo, hi] and the value there.
template <typename F>
std::pair<double, double> goldenSectionMaximum(F&& f, double lo, double hi, double tolerance, int maxSteps = 200) {
  const double inv = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - inv * (hi - lo), x2 = lo + inv * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int step = 0; step < maxSteps && hi - lo > tolerance; ++step) {
    if (f1 >= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - inv * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + inv * (hi - lo);
      f2 = f(x2);
    }
  }
  return f1 >= f2 ? std::pair{x1, f1} : std::pair{x2, f2};
}

}  // namespace linkwright::kinematics
