#include "kinematics/model/driven_linkages.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/validate.h"

namespace linkwright::kinematics {
namespace {

Result<Mechanism> checked(Mechanism m) {
  if (auto e = checkMechanism(m)) return *e;
  return m;
}

}  // namespace

Result<Mechanism> makeTwoLinkArm(const ArmGeometry& g) {
  if (auto e = checkLength(g.upper, "upper")) return *e;
  if (auto e = checkLength(g.forearm, "forearm")) return *e;
  Mechanism m;
  m.lengthUnit = g.lengthUnit;
  m.points = {{"O", GroundPoint{}},
              {"tip", PathPoint{g.tipPath}},
              {"elbow", RrrPoint{PointId{0}, g.upper, PointId{1}, g.forearm, g.elbow}}};
  m.links = {{"upper", PointId{0}, PointId{2}}, {"forearm", PointId{2}, PointId{1}}};
  return checked(std::move(m));
}

Result<Mechanism> makePistonDriven(const PistonDrivenGeometry& g) {
  if (auto e = checkLength(g.crank, "crank")) return *e;
  if (auto e = checkLength(g.rod, "rod")) return *e;
  Mechanism m;
  m.lengthUnit = g.lengthUnit;
  const double innerDeadCentre = g.rod - g.crank;
  m.points = {{"O2", GroundPoint{}},
              {"C", PathPoint{PolylinePath{{{innerDeadCentre, 0.0}, {g.rod + g.crank, 0.0}}}}},
              {"B", RrrPoint{PointId{0}, g.crank, PointId{1}, g.rod, g.branch}}};
  m.links = {{"crank", PointId{0}, PointId{2}}, {"rod", PointId{2}, PointId{1}}};
  return checked(std::move(m));
}

Result<Mechanism> makeCylinderRocker(const CylinderRockerGeometry& g) {
  if (auto e = checkLength(g.eye, "eye")) return *e;
  Mechanism m;
  m.lengthUnit = g.lengthUnit;
  m.points = {{"O", GroundPoint{}},
              {"A", GroundPoint{g.base}},
              {"C", ActuatorPoint{PointId{0}, g.eye, PointId{1}, g.branch}},
              {"tip", AttachedPoint{LinkId{0}, g.tip, 0.0}}};
  m.links = {{"boom", PointId{0}, PointId{2}}};
  return checked(std::move(m));
}

}  // namespace linkwright::kinematics
