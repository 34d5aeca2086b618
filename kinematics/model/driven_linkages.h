#pragma once
// Linkages whose input is not a crank: a two-link arm whose tip is driven along a path (seed
// 004's welding arm), a slider-crank driven from its piston, and a rocker driven by a
// hydraulic cylinder. Each is an ordinary Mechanism (driver.h), so it is solved, tracked,
// tabulated and refined like any other.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <string>

namespace linkwright::kinematics {

/// A two-link arm: shoulder O at the origin, upper link O→elbow (`upper`), forearm
/// elbow→tip (`forearm`), the tip driven along `tipPath`. Elbow Branch::Open puts the elbow to
/// the left of O→tip (counter-clockwise side), as TwoLinkArm's (analysis/two_link_arm.h).
struct ArmGeometry {
  double upper = 0.3;
  double forearm = 0.2;
  PathShape tipPath;
  Branch elbow = Branch::Open;
  std::string lengthUnit = "m";
};

/// Points O, tip, elbow; links upper (O→elbow), forearm (elbow→tip). The input is the tip's
/// path coordinate. Errors name the field ("upper", "forearm", "points[1].path…").
Result<Mechanism> makeTwoLinkArm(const ArmGeometry& geometry);

/// A slider-crank driven from its piston: crank O2→B (`crank`), rod B→C (`rod`), the piston
/// C on the +x axis through O2 driven along it. The input is C's distance from the inner dead
/// centre (x = rod − crank). Branch::Open puts B above the axis.
struct PistonDrivenGeometry {
  double crank = 40.0;
  double rod = 140.0;
  Branch branch = Branch::Open;
  std::string lengthUnit = "mm";
};

/// Points O2, C, B; links crank (O2→B), rod (B→C).
Result<Mechanism> makePistonDriven(const PistonDrivenGeometry& geometry);

/// A rocker (a boom) about ground pivot O, driven by a cylinder from ground pivot A to the
/// boom's eye C at `eye` from O; `tip` is a point further along the boom. The input is the
/// cylinder's length A–C.
struct CylinderRockerGeometry {
  Eigen::Vector2d base = Eigen::Vector2d(0.3, -0.9);  ///< A, from O
  double eye = 1.0;                                   ///< |OC|
  double tip = 2.8;                                   ///< the boom's tip, along O→C from O
  Branch branch = Branch::Open;
  std::string lengthUnit = "m";
};

/// Points O, A, C, tip; link boom (O→C), tip fixed on it.
Result<Mechanism> makeCylinderRocker(const CylinderRockerGeometry& geometry);

}  // namespace linkwright::kinematics
