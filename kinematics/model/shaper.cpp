#include "kinematics/model/shaper.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"

#include <cmath>

namespace linkwright::kinematics {

std::optional<Error> checkShaper(const ShaperGeometry& g) {
  if (auto e = checkLength(g.crank, "crank")) return e;
  if (auto e = checkLength(g.rocker, "rocker")) return e;
  if (auto e = checkLength(g.link, "link")) return e;
  if (auto e = checkCoordinate(g.rockerPivot.x(), "rocker pivot x")) return e;
  if (auto e = checkCoordinate(g.rockerPivot.y(), "rocker pivot y")) return e;
  if (auto e = checkCoordinate(g.guideHeight, "guide height")) return e;
  // Outside the crank circle the slotted link rocks (crank-shaper); inside it turns fully
  // (Whitworth). On the circle the pin would pass through the pivot.
  if (std::abs(g.rockerPivot.norm() - g.crank) <= 1e-12 * g.crank)
    return Error{ErrorCode::InvalidValue, "rocker pivot",
                 "rocker pivot must not lie on the crank circle (distance " + formatNumber(g.rockerPivot.norm()) +
                     ", crank " + formatNumber(g.crank) + "): the crank pin would pass through it"};
  return std::nullopt;
}

Result<Mechanism> makeShaper(const ShaperGeometry& g, Branch branch, const std::string& lengthUnit) {
  if (auto e = checkShaper(g)) return *e;
  Mechanism m;
  m.lengthUnit = lengthUnit;
  m.points = {
      {"O2", GroundPoint{Eigen::Vector2d(0.0, 0.0)}},
      {"O4", GroundPoint{g.rockerPivot}},
      {"B", CrankPoint{shaper::kO2, g.crank, 0.0}},
      {"D", RprPoint{shaper::kO4, shaper::kB, g.rocker}},
      {"R", RrpPoint{shaper::kD, g.link, Guide{std::nullopt, Eigen::Vector2d(0.0, g.guideHeight), 0.0}, branch}},
  };
  m.links = {
      {"crank", shaper::kO2, shaper::kB},
      {"rocker", shaper::kO4, shaper::kD},
      {"link", shaper::kD, shaper::kRam},
  };
  if (auto e = checkLinkageScale(m)) return *e;
  return m;
}

}  // namespace linkwright::kinematics
