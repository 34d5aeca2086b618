#pragma once
// Grashof's criterion for the four-bar (thesis seed 000, §2.4.2, after Myszka): with S and L
// the shortest and longest links and P, Q the other two, at least one link turns fully iff
// S + L ≤ P + Q, and which one depends on where the shortest link is.

#include "kinematics/model/fourbar.h"

#include <string_view>

namespace linkwright::kinematics {

enum class GrashofClass {
  CrankRocker,   ///< S+L < P+Q, shortest link is a side (crank or rocker): it turns fully
  DoubleCrank,   ///< S+L < P+Q, shortest link is the frame: both side links turn fully (drag link)
  DoubleRocker,  ///< S+L < P+Q, shortest link is the coupler: only the coupler turns fully
  ChangePoint,   ///< S+L = P+Q: all four links can become collinear (a singular position)
  TripleRocker,  ///< S+L > P+Q (non-Grashof): no link turns fully relative to another
};

enum class LinkRole { Frame, Crank, Coupler, Rocker };

/// Relative tolerance for S+L = P+Q, as a fraction of the total length S+L+P+Q.
inline constexpr double kChangePointTolerance = 1e-9;

struct GrashofReport {
  GrashofClass category = GrashofClass::TripleRocker;
  LinkRole shortest = LinkRole::Frame;  ///< first of equal shortest links in frame, crank, coupler, rocker order
  LinkRole longest = LinkRole::Frame;
  double sPlusL = 0.0;              ///< S + L, length unit
  double pPlusQ = 0.0;              ///< P + Q, length unit
  bool inputFullyRotates = false;   ///< the crank can turn 360° relative to the frame
  bool outputFullyRotates = false;  ///< the rocker can turn 360° relative to the frame
  bool operator==(const GrashofReport&) const = default;
};

/// Classifies valid (positive, finite) lengths; `tolerance` as kChangePointTolerance.
GrashofReport classifyGrashof(const FourBarLengths& lengths, double tolerance = kChangePointTolerance);

/// "crank-rocker", "double-crank", "double-rocker", "change-point", "triple-rocker".
std::string_view toString(GrashofClass category);
/// "frame", "crank", "coupler", "rocker".
std::string_view toString(LinkRole role);

}  // namespace linkwright::kinematics
