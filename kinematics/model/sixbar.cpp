#include "kinematics/model/sixbar.h"

#include "kinematics/model/attach_dyad.h"
#include "kinematics/model/validate.h"

namespace linkwright::kinematics {
namespace {

// The link that carries P: the coupler for Watt I and Stephenson III, the rocker for Watt II,
// the crank for Stephenson I.
LinkId firstCarrier(SixBarKind kind) {
  switch (kind) {
  case SixBarKind::WattII: return fourbar::kRocker;
  case SixBarKind::StephensonI: return fourbar::kCrank;
  case SixBarKind::WattI:
  case SixBarKind::StephensonIII: break;
  }
  return fourbar::kCoupler;
}

bool groundTernary(SixBarKind kind) { return kind == SixBarKind::WattII || kind == SixBarKind::StephensonIII; }

std::optional<Error> checkGeometry(const SixBarGeometry& g) {
  if (auto e = checkCoordinate(g.first.along, "first.along")) return e;
  if (auto e = checkCoordinate(g.first.across, "first.across")) return e;
  if (groundTernary(g.kind)) {
    if (auto e = checkCoordinate(g.groundPivot.x(), "groundPivot.x")) return e;
    if (auto e = checkCoordinate(g.groundPivot.y(), "groundPivot.y")) return e;
  } else {
    if (auto e = checkCoordinate(g.second.along, "second.along")) return e;
    if (auto e = checkCoordinate(g.second.across, "second.across")) return e;
  }
  if (auto e = checkLength(g.link5, "link5")) return e;
  return checkLength(g.link6, "link6");
}

}  // namespace

std::string sixBarKindName(SixBarKind kind) {
  switch (kind) {
  case SixBarKind::WattI: return "watt-i";
  case SixBarKind::WattII: return "watt-ii";
  case SixBarKind::StephensonI: return "stephenson-i";
  case SixBarKind::StephensonIII: return "stephenson-iii";
  }
  return "six-bar";
}

Result<Mechanism> makeSixBar(const SixBarGeometry& g, const std::string& lengthUnit) {
  if (auto e = checkGeometry(g)) return *e;
  Result<Mechanism> m = makeFourBar(g.fourBar, g.fourBarBranch, lengthUnit);
  if (m) m = addPointOnLink(*m, "P", firstCarrier(g.kind), g.first.along, g.first.across);
  if (m)
    m = groundTernary(g.kind) ? addGroundPivot(*m, "O6", g.groundPivot)
                              : addPointOnLink(*m, "D", fourbar::kRocker, g.second.along, g.second.across);
  if (!m) return m;
  const PointId p{4};
  const PointId d{5};
  return attachDyad(*m, RrrDyadSpec{"E", p, g.link5, d, g.link6, g.dyadBranch});
}

}  // namespace linkwright::kinematics
