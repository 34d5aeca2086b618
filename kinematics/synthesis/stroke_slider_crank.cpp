#include "kinematics/synthesis/stroke_slider_crank.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/synthesis/defects.h"
#include "kinematics/synthesis/message_text.h"
#include "kinematics/synthesis/time_ratio.h"

#include <cmath>

namespace linkwright::kinematics {
namespace {

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

// Crank a, rod b and offset e ≥ 0 for the target, or the error naming the free choice.
Result<SliderCrankGeometry> dimensions(const StrokeTarget& t, double alpha) {
  const double h = t.stroke, tanHalf = std::tan(alpha / 2.0);
  double e = 0.0, b = 0.0;
  if (t.choice == SliderChoice::Rod) {
    b = t.value;
    const double most = alpha > 0.0 ? h / (2.0 * std::sin(alpha / 2.0)) : INFINITY;
    if (!(b > h / 2.0 && b < most))
      return invalid("rod", "rod must be longer than half the stroke (" + formatShort(h / 2.0) + ")" +
                                (alpha > 0.0 ? " and shorter than " + formatShort(most) : std::string()) + " (got " +
                                formatNumber(b) + ")");
    e = (4.0 * b * b - h * h) * tanHalf / (2.0 * h);
  } else {
    e = std::abs(t.value);
    if (alpha == 0.0) {
      if (e != 0.0)
        return invalid("offset", "offset must be 0 for a time ratio of 1 (got " + formatNumber(t.value) + ")");
      return invalid("offset", "with a time ratio of 1 the offset is 0 and the rod is free: choose the rod instead");
    }
    const double most = h / (2.0 * tanHalf);
    if (!(e < most))
      return invalid("offset", "offset must be smaller than " + formatShort(most) +
                                   " in size for this stroke and time ratio (got " + formatNumber(t.value) + ")");
    b = 0.5 * std::sqrt(h * h + 2.0 * h * e / tanHalf);
  }
  const double a = 0.5 * std::sqrt(std::max(0.0, h * h - 2.0 * h * e * tanHalf));
  const std::string field = t.choice == SliderChoice::Rod ? "rod" : "offset";
  if (!(a > 0.0)) return invalid(field, field + " leaves no crank for this stroke and time ratio");
  // Both ends of the stroke on the Open branch: the near end beyond the pivot's foot.
  if (!(4.0 * a * b > h * h))
    return invalid(field, field + " " + formatNumber(t.value) +
                              " puts the ends of the stroke on different assembly branches (no slider-crank reaches "
                              "both): choose a longer rod or a smaller offset");
  return SliderCrankGeometry{a, b, t.choice == SliderChoice::Offset && t.value < 0.0 ? -e : e, false};
}

}  // namespace

Result<SliderCrankSynthesis> synthesiseSliderCrank(const StrokeTarget& t, const DefectBounds& bounds) {
  if (auto e = checkLength(t.stroke, "stroke")) return *e;
  if (auto e = checkTimeRatio(t.timeRatio)) return *e;
  if (t.choice == SliderChoice::Rod) {
    if (auto e = checkLength(t.value, "rod")) return *e;
  } else if (auto e = checkCoordinate(t.value, "offset")) {
    return *e;
  }
  const double alpha = timeRatioAngle(t.timeRatio);
  auto g = dimensions(t, alpha);
  if (!g) return g.error();
  SliderCrankSynthesis s;
  s.geometry = *g;
  const double a = g->crank, b = g->rod, e = g->offset, h = t.stroke;
  s.nearEnd = (4.0 * a * b - h * h) / (2.0 * h);
  s.farEnd = s.nearEnd + h;
  s.extendedCrankAngle = wrapPositive(std::atan2(e, s.farEnd));
  s.foldedCrankAngle = wrapPositive(std::atan2(e, s.nearEnd) + kPi);
  auto m = makeSliderCrank(*g, Branch::Open, t.lengthUnit);
  if (!m) return m.error();
  Design d;
  d.kind = "slider-crank";
  d.mechanism = std::move(*m);
  // The rod swings furthest from the guide with the crank square to it: sin β = (a + |e|)/b.
  std::vector<Defect> defects;
  double mu = 0.0;
  if (a + std::abs(e) < b) {
    mu = kPi / 2.0 - std::asin((a + std::abs(e)) / b);
  } else {
    defects.push_back({DefectKind::NotGrashof, "the crank cannot turn fully: crank + offset (" +
                                                   formatShort(a + std::abs(e)) + ") is not shorter than the rod (" +
                                                   formatShort(b) + ")"});
  }
  if (auto defect = transmissionDefect(mu, bounds)) defects.push_back(*defect);
  if (auto defect = linkLengthDefect({a, b}, {"crank", "rod"}, bounds)) defects.push_back(*defect);
  s.candidate = {std::move(d), 0.0, std::nullopt, mu, std::move(defects)};
  return s;
}

}  // namespace linkwright::kinematics
