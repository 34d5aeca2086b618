#include "kinematics/design/design_analysis.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"

#include <algorithm>

namespace linkwright::kinematics {
namespace {

// An angle brought into [0, 2π), as the four-bar analyses give crank angles.
double oneTurn(double angle) {
  const double a = wrapAngle(angle);
  return a < 0.0 ? a + 2.0 * kPi : a;
}

// The four-bar analyses measure the crank from the frame line; the mechanism's input angle
// differs by the frame's direction and the crank's phase (zero for makeFourBar's four-bars,
// which are then left bit for bit as the closed forms give them).
void toInputAngles(const FourBarStructure& s, DesignAnalysis& a) {
  const double shift = s.inputAngle(0.0);
  if (shift == 0.0) return;
  for (AngleRange& r : a.inputRange.ranges) {
    r.from += shift;
    r.to += shift;
  }
  if (a.transmission) {
    a.transmission->minimumAtCrank = oneTurn(a.transmission->minimumAtCrank + shift);
    a.transmission->maximumAtCrank = oneTurn(a.transmission->maximumAtCrank + shift);
  }
  for (LimitPosition& p : a.limits.positions) {
    p.crankAngle = oneTurn(p.crankAngle + shift);
    p.rockerAngle = wrapAngle(p.rockerAngle + s.frameAngle);
  }
  std::sort(a.limits.positions.begin(), a.limits.positions.end(),
            [](const LimitPosition& x, const LimitPosition& y) { return x.crankAngle < y.crankAngle; });
}

}  // namespace

InputRange assembledRange(const SweepResult& sweep, InputKind input) {
  InputRange range;
  if (input == InputKind::Length) range.period = 0.0;
  std::size_t j = 0;
  while (j < sweep.size()) {
    if (!sweep.assembled(j)) {
      ++j;
      continue;
    }
    const std::size_t first = j;
    while (j + 1 < sweep.size() && sweep.assembled(j + 1) && !sweep.lockedAfter(j)) ++j;
    range.ranges.push_back({sweep.inputAngle[first], sweep.inputAngle[j]});
    ++j;
  }
  const bool everySample = range.ranges.size() == 1 && sweep.notAssembled.empty();
  const double span = sweep.size() > 1 ? sweep.inputAngle.back() - sweep.inputAngle.front() : 0.0;
  range.fullRotation = input == InputKind::Angle && everySample && span >= 2.0 * kPi * (1.0 - 1e-12);
  if (range.fullRotation) range.ranges.clear();
  return range;
}

std::optional<Error> assemblesNowhere(const Mechanism& mechanism, const SweepResult& gridSweep) {
  const auto nowhere = [](const std::string& why) {
    return Error{ErrorCode::NotAssemblable, "design", "This linkage cannot be assembled at any " + why};
  };
  if (const auto fourBar = asFourBar(mechanism, PointsOnLinks::AnyLink)) {
    const InputRange range = fourBarInputRange(fourBar->lengths);
    if (!range.ranges.empty() || range.fullRotation) return std::nullopt;
    return nowhere("crank angle: the coupler and rocker cannot reach between the crank tip and the rocker pivot.");
  }
  const bool assembles = std::any_of(gridSweep.report.begin(), gridSweep.report.end(),
                                     [](const PoseReport& r) { return r.status != PoseStatus::NotAssemblable; });
  if (assembles) return std::nullopt;
  const std::string input = inputKind(mechanism) == InputKind::Angle ? "crank angle" : "input position";
  return nowhere(input + (gridSweep.firstFailure ? ": " + *gridSweep.firstFailure + "." : "."));
}

DesignAnalysis analyseDesign(const Mechanism& mechanism, const SweepResult& gridSweep) {
  DesignAnalysis a;
  a.mobility = mobility(mechanism);
  a.notAssembled = gridSweep.notAssembled;
  if (const auto fourBar = asFourBar(mechanism, PointsOnLinks::AnyLink)) {
    a.grashof = classifyGrashof(fourBar->lengths);
    a.inputRange = fourBarInputRange(fourBar->lengths);
    a.transmission = fourBarTransmissionRange(fourBar->lengths);
    a.limits = fourBarLimitPositions(fourBar->lengths, fourBar->branch);
    toInputAngles(*fourBar, a);
    return a;
  }
  a.inputRange = assembledRange(gridSweep, inputKind(mechanism));
  if (const auto q = asQuickReturn(mechanism)) a.quickReturn = shaperQuickReturn(q->geometry, q->ramBranch);
  return a;
}

}  // namespace linkwright::kinematics
