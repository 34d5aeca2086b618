#include "ui/document/design_analysis.h"

#include "kinematics/model/units.h"

#include <variant>

namespace linkwright::ui {

namespace k = kinematics;

k::InputRange assembledRange(const k::SweepResult& sweep) {
  k::InputRange range;
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
  range.fullRotation = everySample && span >= 2.0 * k::kPi * (1.0 - 1e-12);
  if (range.fullRotation) range.ranges.clear();
  return range;
}

std::optional<k::ShaperGeometry> shaperGeometryOf(const k::Mechanism& m, k::Branch* ramBranch) {
  if (m.points.size() != 5 || m.links.size() != 3) return std::nullopt;
  const auto* o2 = std::get_if<k::GroundPoint>(&m.points[0].definition);
  const auto* o4 = std::get_if<k::GroundPoint>(&m.points[1].definition);
  const auto* b = std::get_if<k::CrankPoint>(&m.points[2].definition);
  const auto* d = std::get_if<k::RprPoint>(&m.points[3].definition);
  const auto* r = std::get_if<k::RrpPoint>(&m.points[4].definition);
  if (!o2 || !o4 || !b || !d || !r) return std::nullopt;
  if (b->pivot != k::PointId{0} || d->pivot != k::PointId{1} || d->through != k::PointId{2} || r->first != k::PointId{3})
    return std::nullopt;
  // ShaperGeometry's ram guide is horizontal and fixed to the ground; O2 is its origin.
  if (r->guide.link || r->guide.angle != 0.0) return std::nullopt;
  if (ramBranch != nullptr) *ramBranch = r->branch;
  return k::ShaperGeometry{b->length, d->length, r->length, o4->position - o2->position,
                           r->guide.point.y() - o2->position.y()};
}

DesignAnalysis analyseDesign(const k::Design& design, const k::Mechanism& mechanism, const k::SweepResult& sweep) {
  DesignAnalysis a;
  a.mobility = k::mobility(mechanism);
  a.notAssembled = sweep.notAssembled;
  if (const auto* fourBar = std::get_if<k::FourBarDesign>(&design)) {
    a.grashof = k::classifyGrashof(fourBar->lengths);
    a.inputRange = k::fourBarInputRange(fourBar->lengths);
    a.transmission = k::fourBarTransmissionRange(fourBar->lengths);
    a.limits = k::fourBarLimitPositions(fourBar->lengths, fourBar->branch);
    return a;
  }
  a.inputRange = assembledRange(sweep);
  const auto& kind = std::get<k::MechanismDesign>(design).kind;
  k::Branch branch = k::Branch::Open;
  if (kind == "shaper" || kind == "whitworth")
    if (const auto geometry = shaperGeometryOf(mechanism, &branch)) a.quickReturn = k::shaperQuickReturn(*geometry, branch);
  return a;
}

} // namespace linkwright::ui
