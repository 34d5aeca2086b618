#include "kinematics/analysis/transmission.h"

#include "kinematics/model/units.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace linkwright::kinematics {
namespace {

double diagonal(const FourBarLengths& l, double crankAngle) {
  return std::sqrt(
      std::max(0.0, l.crank * l.crank + l.frame * l.frame - 2.0 * l.crank * l.frame * std::cos(crankAngle)));
}

double angleForDiagonal(const FourBarLengths& l, double bd) {
  const double c = (l.coupler * l.coupler + l.rocker * l.rocker - bd * bd) / (2.0 * l.coupler * l.rocker);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

double crankForDiagonal(const FourBarLengths& l, double bd) {
  const double c = (l.crank * l.crank + l.frame * l.frame - bd * bd) / (2.0 * l.crank * l.frame);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

}  // namespace

std::optional<double> fourBarTransmissionAngle(const FourBarLengths& l, double crankAngle) {
  const double bd = diagonal(l, crankAngle);
  const double slack = 1e-10 * (l.coupler + l.rocker);
  if (bd > l.coupler + l.rocker + slack || bd < std::abs(l.coupler - l.rocker) - slack) return std::nullopt;
  return angleForDiagonal(l, bd);
}

std::optional<TransmissionRange> fourBarTransmissionRange(const FourBarLengths& l) {
  // BD sweeps [|d−a|, d+a] over a turn; the loop closes for BD in [|b−c|, b+c].
  const double low = std::max(std::abs(l.frame - l.crank), std::abs(l.coupler - l.rocker));
  const double high = std::min(l.frame + l.crank, l.coupler + l.rocker);
  if (low > high * (1.0 + 1e-12)) return std::nullopt;
  TransmissionRange r;
  r.minimum = angleForDiagonal(l, low);  // μ grows with BD
  r.maximum = angleForDiagonal(l, std::max(low, high));
  r.minimumAtCrank = crankForDiagonal(l, low);
  r.maximumAtCrank = crankForDiagonal(l, std::max(low, high));
  r.worstDeviation = std::max(std::abs(r.minimum - kPi / 2.0), std::abs(r.maximum - kPi / 2.0));
  return r;
}

std::optional<double> worstTransmissionBetween(const FourBarLengths& l, double from, double to) {
  const double lo = std::min(from, to), hi = std::max(from, to);
  std::vector<double> at{lo, hi};
  for (double k = std::ceil(lo / kPi); k * kPi < hi; k += 1.0) at.push_back(k * kPi);
  double worst = kPi / 2.0;
  for (const double theta : at) {
    const auto mu = fourBarTransmissionAngle(l, theta);
    if (!mu) return std::nullopt;
    worst = std::min(worst, std::min(*mu, kPi - *mu));
  }
  return worst;
}

}  // namespace linkwright::kinematics
