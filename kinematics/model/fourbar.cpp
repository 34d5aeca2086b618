#include "kinematics/model/fourbar.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/validate.h"

namespace linkwright::kinematics {

std::optional<Error> checkFourBarLengths(const FourBarLengths& l) {
  if (auto e = checkLength(l.frame, "frame")) return e;
  if (auto e = checkLength(l.crank, "crank")) return e;
  if (auto e = checkLength(l.coupler, "coupler")) return e;
  return checkLength(l.rocker, "rocker");
}

Result<Mechanism> makeFourBar(const FourBarLengths& l, Branch branch, const std::string& lengthUnit,
                              std::optional<CouplerPointSpec> couplerPoint) {
  if (auto e = checkFourBarLengths(l)) return *e;
  if (couplerPoint) {
    if (auto e = checkCoordinate(couplerPoint->along, "coupler point along")) return *e;
    if (auto e = checkCoordinate(couplerPoint->across, "coupler point across")) return *e;
  }
  Mechanism m;
  m.lengthUnit = lengthUnit;
  m.points = {
      {"O2", GroundPoint{Eigen::Vector2d(0.0, 0.0)}},
      {"O4", GroundPoint{Eigen::Vector2d(l.frame, 0.0)}},
      {"B", CrankPoint{fourbar::kO2, l.crank, 0.0}},
      {"C", RrrPoint{fourbar::kB, l.coupler, fourbar::kO4, l.rocker, branch}},
  };
  m.links = {
      {"crank", fourbar::kO2, fourbar::kB},
      {"coupler", fourbar::kB, fourbar::kC},
      {"rocker", fourbar::kO4, fourbar::kC},
  };
  if (couplerPoint)
    m.points.push_back({"P", AttachedPoint{fourbar::kCoupler, couplerPoint->along, couplerPoint->across}});
  if (auto e = checkLinkageScale(m)) return *e;
  return m;
}

}  // namespace linkwright::kinematics
