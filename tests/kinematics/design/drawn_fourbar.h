#pragma once
// A four-bar built point by point as a user might draw it, the way makeFourBar does not: O4
// defined first, the frame line pointing at 30° from a pivot O2 away from the origin, the
// crank with a phase, C's parents in the order (O4, B) and the coupler link running C→B. The
// design tests edit it by its four-bar dimensions and compare it with makeFourBar's.

#include "kinematics/model/fourbar.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/units.h"

#include <Eigen/Core>

#include <cmath>
#include <optional>

namespace linkwright::test {

struct DrawnFourBar {
  kinematics::Mechanism mechanism;
  Eigen::Vector2d origin;   ///< O2
  double frameAngle = 0.0;  ///< direction O2→O4, rad
  double crankPhase = 0.0;  ///< rad
};

inline constexpr kinematics::PointId kDrawnO4{0};
inline constexpr kinematics::PointId kDrawnO2{1};
inline constexpr kinematics::PointId kDrawnB{2};
inline constexpr kinematics::PointId kDrawnC{3};
inline constexpr kinematics::PointId kDrawnP{4};  ///< present only with a coupler point

/// The four-bar with `lengths` on four-bar `branch` (open: C left of B→O4), O2 at (100, 50),
/// the frame at 30°, the crank's phase 10°, and P at `couplerPoint` (along B→C, across 90° CCW
/// from it) on the coupler link C→B.
inline DrawnFourBar drawnFourBar(const kinematics::FourBarLengths& lengths, kinematics::Branch branch,
                                 std::optional<kinematics::CouplerPointSpec> couplerPoint = std::nullopt) {
  using namespace linkwright::kinematics;
  DrawnFourBar d{Mechanism{}, Eigen::Vector2d(100.0, 50.0), degToRad(30.0), degToRad(10.0)};
  // Parents (O4, B): the dyad's open side, left of O4→B, is the four-bar's crossed one.
  const Branch dyadBranch = branch == Branch::Open ? Branch::Crossed : Branch::Open;
  Mechanism& m = d.mechanism;
  m.points = {
      {"O4", GroundPoint{d.origin + lengths.frame * Eigen::Vector2d(std::cos(d.frameAngle), std::sin(d.frameAngle))}},
      {"O2", GroundPoint{d.origin}},
      {"B", CrankPoint{kDrawnO2, lengths.crank, d.crankPhase}},
      {"C", RrrPoint{kDrawnO4, lengths.rocker, kDrawnB, lengths.coupler, dyadBranch}}};
  m.links = {{"crank", kDrawnO2, kDrawnB}, {"coupler", kDrawnC, kDrawnB}, {"rocker", kDrawnO4, kDrawnC}};
  // On the link C→B, "along" runs from C toward B and "across" is 90° CCW from C→B.
  if (couplerPoint)
    m.points.push_back({"P", AttachedPoint{LinkId{1}, lengths.coupler - couplerPoint->along, -couplerPoint->across}});
  return d;
}

}  // namespace linkwright::test
