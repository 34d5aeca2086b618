#include "kinematics/analysis/extrema.h"

#include "kinematics/solve/pose_solver.h"

#include <cmath>

namespace linkwright::kinematics {
namespace {

// Golden-section search for the maximum of `sign`·f on [lo, hi]; returns the best (angle,
// value) among the ends and the interior points it visited.
struct Search {
  const Mechanism& mechanism;
  const SweepSpec& spec;
  const PoseQuantity& quantity;
  Pose pose;

  std::optional<double> evaluate(double angle) {
    const PoseReport r = solvePoseInto(mechanism, {angle, spec.omega, spec.alpha}, {true, true}, pose);
    if (r.status != PoseStatus::Ok) return std::nullopt;
    return quantity(pose, angle);
  }

  Extremum maximize(double lo, double hi, double sign, const Extremum& start, double tolerance) {
    constexpr double kInvPhi = 0.6180339887498949;
    Extremum best = start;
    auto consider = [&](double angle, std::optional<double> v) {
      if (v && sign * *v > sign * best.value) best = {*v, angle, true};
      return v ? sign * *v : -INFINITY;
    };
    double a = lo, b = hi;
    double x1 = b - kInvPhi * (b - a), x2 = a + kInvPhi * (b - a);
    double f1 = consider(x1, evaluate(x1)), f2 = consider(x2, evaluate(x2));
    for (int i = 0; i < 200 && b - a > tolerance; ++i) {
      if (f1 < f2) {
        a = x1;
        x1 = x2;
        f1 = f2;
        x2 = a + kInvPhi * (b - a);
        f2 = consider(x2, evaluate(x2));
      } else {
        b = x2;
        x2 = x1;
        f2 = f1;
        x1 = b - kInvPhi * (b - a);
        f1 = consider(x1, evaluate(x1));
      }
    }
    return best;
  }
};

} // namespace

std::optional<Extrema> refineExtrema(const Mechanism& mechanism, const SweepSpec& spec, const std::vector<double>& values,
                                     const std::vector<bool>& valid, const PoseQuantity& quantity, double angleTolerance) {
  std::optional<std::size_t> lowest, highest;
  for (std::size_t j = 0; j < values.size(); ++j) {
    if (!valid[j]) continue;
    if (!lowest || values[j] < values[*lowest]) lowest = j;
    if (!highest || values[j] > values[*highest]) highest = j;
  }
  if (!lowest) return std::nullopt;
  Search search{mechanism, spec, quantity, {}};
  preparePose(mechanism, search.pose);
  // The bracket: from the best sample's valid neighbours (or the sample itself at an end).
  auto bracket = [&](std::size_t j) {
    const double lo = j > 0 && valid[j - 1] ? sweepAngle(spec, j - 1) : sweepAngle(spec, j);
    const double hi = j + 1 < values.size() && valid[j + 1] ? sweepAngle(spec, j + 1) : sweepAngle(spec, j);
    return std::pair{std::min(lo, hi), std::max(lo, hi)};
  };
  Extrema out;
  const auto [minLo, minHi] = bracket(*lowest);
  out.minimum = search.maximize(minLo, minHi, -1.0, {values[*lowest], sweepAngle(spec, *lowest), false}, angleTolerance);
  const auto [maxLo, maxHi] = bracket(*highest);
  out.maximum = search.maximize(maxLo, maxHi, 1.0, {values[*highest], sweepAngle(spec, *highest), false}, angleTolerance);
  return out;
}

} // namespace linkwright::kinematics
