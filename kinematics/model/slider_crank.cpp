#include "kinematics/model/slider_crank.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

namespace linkwright::kinematics {

std::optional<Error> checkSliderCrank(const SliderCrankGeometry& g) {
  if (auto e = checkLength(g.crank, "crank")) return e;
  if (auto e = checkLength(g.rod, "rod")) return e;
  return checkCoordinate(g.offset, "offset");
}

Result<Mechanism> makeSliderCrank(const SliderCrankGeometry& g, Branch branch, const std::string& lengthUnit) {
  if (auto e = checkSliderCrank(g)) return *e;
  Mechanism m;
  m.lengthUnit = lengthUnit;
  m.points = {
      {"O2", GroundPoint{Eigen::Vector2d(0.0, 0.0)}},
      {"B", CrankPoint{slidercrank::kO2, g.crank, 0.0}},
      {"C", RrpPoint{slidercrank::kB, g.rod,
                     Guide{std::nullopt, Eigen::Vector2d(0.0, g.offset), g.reversed ? kPi : 0.0}, branch}},
  };
  m.links = {
      {"crank", slidercrank::kO2, slidercrank::kB},
      {"rod", slidercrank::kB, slidercrank::kC},
  };
  if (auto e = checkLinkageScale(m)) return *e;
  return m;
}

}  // namespace linkwright::kinematics
