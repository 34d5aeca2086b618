#pragma once
// Four-bar motion generation for two and three coupler poses (the circle-point / centre-point
// construction, Burmester's for three poses; as in Norton, Sandor & Erdman, Waldron & Kinzel).
// A pose is a coupler point P and the coupler's angle φ. A point fixed on the coupler (a circle
// point), given where it is at pose 1, is at pose j at
//   p_j = P_j + R(φ_j − φ_1)·(p_1 − P_1),
// and a crank pinned to the ground at the centre of the circle through the p_j carries it
// through all of them: with three poses that centre (the centre point) is the circumcentre of
// p_1, p_2, p_3; with two, any point of the perpendicular bisector of p_1p_2 (the free choice,
// given as a signed distance along it). Two circle points A and B, with their centre points
// O2 and O4, make the four-bar O2–A–B–O4 with the pose point riding on the coupler AB: it
// passes through every pose exactly, provided it reaches them on one assembly branch and in
// order, which the defect check reports.
//
// The linkage's ground pivots are where the construction puts them (the frame may tilt): the
// mechanism is built point by point as makeFourBar would (points O2, O4, B (= A here), C (= B
// here), P; links crank, coupler, rocker), and its input is the crank's absolute angle (CCW
// from +x), which asFourBar (model/recognise.h) recognises with its frame angle.

#include "kinematics/design/synthesis_targets.h"
#include "kinematics/synthesis/candidate.h"
#include "kinematics/synthesis/defects.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace linkwright::kinematics {

struct MotionSynthesis {
  Eigen::Vector2d o2 = Eigen::Vector2d::Zero();  ///< the crank's centre point (ground pivot)
  Eigen::Vector2d o4 = Eigen::Vector2d::Zero();  ///< the rocker's centre point (ground pivot)
  std::vector<Eigen::Vector2d> a;                ///< circle point A at each pose
  std::vector<Eigen::Vector2d> b;                ///< circle point B at each pose
  std::vector<double> crankAngles;               ///< the design's input (crank's absolute angle, rad) at each pose
  FourBarLengths lengths;
  Branch branch = Branch::Open;  ///< the branch at pose 1 (fourbar.h's convention)
  /// design: the four-bar with P on its coupler, graded from pose 1 to the last pose; error 0
  /// (exact); minTransmission over that motion.
  SynthesisCandidate candidate;
};

/// Options shared by both constructions.
struct MotionOptions {
  bool needsFullRotation = false;  ///< a motor turns the crank round (a Grashof crank is then required)
  std::string lengthUnit = "mm";
};

/// Three poses. Error naming the field ("poses[1]", "circlePoints.a", …) for non-finite or
/// coincident poses, or a circle point whose three positions are collinear (no centre point)
/// or which is its own centre (the poses' rotation pole: a crank of zero length).
Result<MotionSynthesis> synthesiseMotion3(const std::vector<CouplerPose>& poses, const CirclePoints& circlePoints,
                                          const DefectBounds& bounds = {}, const MotionOptions& options = {});

/// Two poses; `centreA` and `centreB` place each centre point on its perpendicular bisector, as
/// a signed distance (length unit) from the midpoint of the circle point's two positions,
/// positive to the left of the direction from its first position to its second.
Result<MotionSynthesis> synthesiseMotion2(const std::vector<CouplerPose>& poses, const CirclePoints& circlePoints,
                                          double centreA, double centreB, const DefectBounds& bounds = {},
                                          const MotionOptions& options = {});

}  // namespace linkwright::kinematics
