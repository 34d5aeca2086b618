#include "kinematics/analysis/assembly_range.h"

#include "kinematics/model/units.h"

#include <cmath>

namespace linkwright::kinematics {

bool InputRange::contains(double angle, double tolerance) const {
  if (fullRotation) return true;
  for (const AngleRange& r : ranges) {
    if (period == 0.0) {
      if (angle >= r.from - tolerance && angle <= r.to + tolerance) return true;
      continue;
    }
    // Shift the angle into the turn that starts at r.from.
    const double shifted = r.from + std::fmod(std::fmod(angle - r.from, period) + period, period);
    if (shifted <= r.to + tolerance || shifted - period >= r.from - tolerance) return true;
  }
  return false;
}

double InputRange::clamp(double angle) const {
  if (ranges.empty() || contains(angle)) return angle;
  double best = angle;
  double bestDistance = INFINITY;
  for (const AngleRange& r : ranges) {
    for (const double edge : {r.from, r.to}) {
      const double distance = period == 0.0 ? std::abs(angle - edge) : std::abs(std::remainder(angle - edge, period));
      if (distance < bestDistance) {
        bestDistance = distance;
        best = edge;
      }
    }
  }
  return best;
}

InputRange fourBarInputRange(const FourBarLengths& l) {
  const double a = l.crank;
  const double d = l.frame;
  const double twoAD = 2.0 * a * d;
  const double base = a * a + d * d;
  const double lowCos = (base - (l.coupler + l.rocker) * (l.coupler + l.rocker)) / twoAD;
  const double highCos = (base - (l.coupler - l.rocker) * (l.coupler - l.rocker)) / twoAD;
  InputRange out;
  if (lowCos > 1.0 || highCos < -1.0 || lowCos > highCos) return out;  // never assembles
  const bool lowFree = lowCos <= -1.0;                                 // cos θ ≥ lowCos holds for every θ
  const bool highFree = highCos >= 1.0;                                // cos θ ≤ highCos holds for every θ
  if (lowFree && highFree) {
    out.fullRotation = true;
    out.ranges.push_back({0.0, 2.0 * kPi});
    return out;
  }
  const double farEdge = lowFree ? kPi : std::acos(lowCos);     // largest |θ| allowed
  const double nearEdge = highFree ? 0.0 : std::acos(highCos);  // smallest |θ| allowed
  if (highFree) {
    out.ranges.push_back({-farEdge, farEdge});
  } else if (lowFree) {
    out.ranges.push_back({nearEdge, 2.0 * kPi - nearEdge});
  } else {
    out.ranges.push_back({nearEdge, farEdge});
    out.ranges.push_back({-farEdge, -nearEdge});
  }
  return out;
}

}  // namespace linkwright::kinematics
