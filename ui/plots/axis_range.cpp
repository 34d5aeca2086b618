#include "ui/plots/axis_range.h"

#include <algorithm>
#include <cmath>

namespace linkwright::ui {
namespace {

// Ticks in degrees that read well on a crank axis; past the last, niceStep takes over.
constexpr double kDegreeSteps[] = {1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 90.0, 180.0, 360.0};
// At most 4 intervals (90° over a turn): the plots share the window with the canvas and a
// legend, and wider labels would be elided ("1…") at the plot widths the window gives.
constexpr int kCrankIntervals = 4;

}  // namespace

double niceStep(double raw) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / magnitude;
  // Relative slack so that 0.2 / 0.1 (= 2.0000000000000004) still counts as 2.
  constexpr double kSlack = 1e-9;
  for (const double nice : {1.0, 2.0, 2.5, 5.0})
    if (norm <= nice * (1.0 + kSlack)) return nice * magnitude;
  return 10.0 * magnitude;
}

int decimalsFor(double step) {
  for (int d = 0; d < 6; ++d) {
    const double scaled = step * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, scaled)) return d;
  }
  return 6;
}

AxisRange niceValueRange(double lo, double hi, int maxTicks) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) return {};
  const double scale = std::max({1.0, std::abs(lo), std::abs(hi)});
  if (hi - lo <= 1e-9 * scale) {
    const double pad = lo != 0.0 ? 0.1 * std::abs(lo) : 1.0;
    lo -= pad;
    hi += pad;
  } else {
    const double margin = 0.05 * (hi - lo);
    lo -= margin;
    hi += margin;
  }
  const double step = niceStep((hi - lo) / std::max(1, maxTicks - 1));
  AxisRange r;
  // The small slack keeps a bound that is already a multiple of step from moving a step out.
  r.min = std::floor(lo / step + 1e-9) * step;
  r.max = std::ceil(hi / step - 1e-9) * step;
  r.step = step;
  r.tickCount = static_cast<int>(std::lround((r.max - r.min) / step)) + 1;
  r.decimals = decimalsFor(step);
  return r;
}

bool keepsRange(const AxisRange& shown, double lo, double hi) {
  constexpr double kLeastFill = 0.5;
  const double span = shown.max - shown.min;
  return std::isfinite(lo) && std::isfinite(hi) && lo <= hi && span > 0.0 && lo >= shown.min && hi <= shown.max &&
         hi - lo >= kLeastFill * span;
}

AxisRange refittedRange(double lo, double hi, DataFlow flow, int maxTicks) {
  const AxisRange tight = niceValueRange(lo, hi, maxTicks);
  if (flow == DataFlow::Settled || !(hi > lo)) return tight;
  // Rounding out to a coarser step can leave the data less than half the axis: then less room.
  for (const double room : {0.2, 0.1, 0.05}) {
    const AxisRange roomy = niceValueRange(lo - room * (hi - lo), hi + room * (hi - lo), maxTicks);
    if (keepsRange(roomy, lo, hi)) return roomy;
  }
  return tight;
}

AxisRange crankAxisRange(double fromDeg, double toDeg, AngleUnit unit) {
  const double spanDeg = std::max(std::abs(toDeg - fromDeg), 1e-9);
  double stepDeg = 0.0;
  for (const double s : kDegreeSteps) {
    if (spanDeg / s <= kCrankIntervals) {
      stepDeg = s;
      break;
    }
  }
  AxisRange r;
  r.min = toAngleUnit(kinematics::degToRad(std::min(fromDeg, toDeg)), unit);
  r.max = toAngleUnit(kinematics::degToRad(std::max(fromDeg, toDeg)), unit);
  if (unit == AngleUnit::Degrees && stepDeg > 0.0) r.step = stepDeg;
  else r.step = niceStep((r.max - r.min) / kCrankIntervals);
  r.tickCount = static_cast<int>(std::floor((r.max - r.min) / r.step + 1e-9)) + 1;
  r.decimals = decimalsFor(r.step);
  return r;
}

std::optional<double> wrapIntoRange(double angleDeg, double fromDeg, double toDeg) {
  constexpr double kTurn = 360.0;
  constexpr double kTolerance = 1e-9;  // degrees; absorbs rad→deg round-off at the grid ends
  double x = fromDeg + std::fmod(angleDeg - fromDeg, kTurn);
  if (x < fromDeg - kTolerance) x += kTurn;
  if (x > fromDeg + kTurn - kTolerance) x -= kTurn;  // a hair below a whole turn from the start
  if (x < fromDeg) x = fromDeg;
  if (x <= toDeg + kTolerance) return std::min(x, toDeg);
  return std::nullopt;
}

std::pair<double, double> robustSpan(std::vector<double>& values, double tail) {
  if (values.empty()) return {0.0, 0.0};
  // Two selections and a scan, not a sort: this runs on every frame of a drag.
  const auto at = [&](double q) {
    const auto nth = values.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), nth, values.end());
    return *nth;
  };
  const double lo = at(tail);
  const double hi = at(1.0 - tail);
  const auto [least, most] = std::minmax_element(values.begin(), values.end());
  const double margin = 0.5 * (hi - lo);
  return {std::max(*least, lo - margin), std::min(*most, hi + margin)};
}

}  // namespace linkwright::ui
