#pragma once
// Golden-section search: the extremum of a function of one variable that has one extremum in
// [lo, hi]. Each step keeps the sub-interval holding the better of two interior values, which
// shrinks the bracket by 0.618 for one new evaluation (the other interior point is kept). It
// needs no derivative, so it suits what the core refines between samples: a quantity's extremum
// on the pose solver (extrema.h), a periodic series' peak, a coupler curve's cusp and symmetry
// axis, the synthesis objectives that are a minimum of two smooth pieces or an absolute value,
// a compared table's offset. Callers bracket the extremum first by sampling. The search stops
// after `maxSteps` steps or when the bracket is within `tolerance` (the variable's unit), and f
// is evaluated in order: x1, x2, then one new point per step (a caller may record every value).
// It is the core's one copy: one rule for ties (below), one golden ratio.

#include <utility>

namespace linkwright::kinematics {

/// 1/φ = (√5 − 1)/2, the share of the bracket each step keeps.
inline constexpr double kInverseGoldenRatio = 0.6180339887498949;

/// Which extremum a golden-section search looks for.
enum class GoldenGoal { Minimum, Maximum };

/// Where a golden-section search ended: the bracket and its two interior points.
struct GoldenSearch {
  GoldenGoal goal = GoldenGoal::Minimum;
  double lo = 0.0, hi = 0.0;  ///< the last bracket
  double x1 = 0.0, f1 = 0.0;  ///< the lower interior point and f there
  double x2 = 0.0, f2 = 0.0;  ///< the upper interior point and f there
  /// The bracket's midpoint: the extremum's place to within half the bracket.
  double middle() const { return 0.5 * (lo + hi); }
  /// The better interior point and f there (x1 on a tie).
  std::pair<double, double> best() const {
    const bool first = goal == GoldenGoal::Maximum ? f1 >= f2 : f1 <= f2;
    return first ? std::pair{x1, f1} : std::pair{x2, f2};
  }
};

/// The golden-section search for `goal` of f on [lo, hi]. A tie keeps [x1, hi] when minimising and
/// [lo, x2] when maximising (the extremum of a unimodal f lies between x1 and x2 then, so either is
/// right; this is the rule every search of the core had). f must not return NaN.
template <typename F>
GoldenSearch goldenSection(F&& f, double lo, double hi, GoldenGoal goal, double tolerance, int maxSteps = 200) {
  constexpr double g = kInverseGoldenRatio;
  GoldenSearch s{goal, lo, hi, hi - g * (hi - lo), 0.0, lo + g * (hi - lo), 0.0};
  s.f1 = f(s.x1);
  s.f2 = f(s.x2);
  for (int step = 0; step < maxSteps && s.hi - s.lo > tolerance; ++step) {
    const bool left = goal == GoldenGoal::Maximum ? !(s.f1 < s.f2) : s.f1 < s.f2;
    if (left) {
      s.hi = s.x2;
      s.x2 = s.x1;
      s.f2 = s.f1;
      s.x1 = s.hi - g * (s.hi - s.lo);
      s.f1 = f(s.x1);
    } else {
      s.lo = s.x1;
      s.x1 = s.x2;
      s.f1 = s.f2;
      s.x2 = s.lo + g * (s.hi - s.lo);
      s.f2 = f(s.x2);
    }
  }
  return s;
}

/// The minimum of f on [lo, hi] by golden section (goldenSection with GoldenGoal::Minimum).
template <typename F>
GoldenSearch goldenSectionMinimum(F&& f, double lo, double hi, double tolerance, int maxSteps = 200) {
  return goldenSection(std::forward<F>(f), lo, hi, GoldenGoal::Minimum, tolerance, maxSteps);
}

/// The maximum of f on [lo, hi] by golden section (goldenSection with GoldenGoal::Maximum).
template <typename F>
GoldenSearch goldenSectionMaximum(F&& f, double lo, double hi, double tolerance, int maxSteps = 200) {
  return goldenSection(std::forward<F>(f), lo, hi, GoldenGoal::Maximum, tolerance, maxSteps);
}

}  // namespace linkwright::kinematics
