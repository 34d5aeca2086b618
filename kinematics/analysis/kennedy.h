#pragma once
// Kennedy's circle diagram: the secondary instant centres from the primary ones. The three
// centres of any three bodies i, j, k lie on one line, so an unknown Iij lies on the line
// Iik–Ijk for every body k whose two centres are known; where two such lines meet is Iij.
//
//   Passes. Each pass locates every unknown centre that two lines reach, from the centres known
//   when the pass began (so the result does not depend on the order pairs are visited), and
//   repeats until a pass finds nothing. Of the lines reaching a centre, the two that cross at
//   the widest angle locate it: their intersection has the least round-off.
//   Lines. Through two finite centres; through a finite one in the direction of one at
//   infinity; the line at infinity through two at infinity (it meets a finite line at that
//   line's point at infinity). Two centres closer than kCentreTolerance·scale give no line.
//   Degenerate meetings. Parallel lines meet at infinity. If every pair of lines reaching a
//   centre coincides, the centre is Indeterminate (a four-bar with all joints in one line); it
//   is decided only after no pass finds more, so a centre that other lines reach later is not
//   lost. A centre no two lines reach stays Unresolved.

#include "kinematics/analysis/instant_centres.h"

namespace linkwright::kinematics {

/// Completes `centres`: its bodies, scale and primary centres (rule Pin or Slide) are set,
/// every other centre is Unresolved with rule None. Fills in the secondary centres (rule
/// Kennedy, with the bodies whose lines located them) as the header describes.
void completeByKennedy(InstantCentres& centres);

/// The point at infinity in direction d (any nonzero length), normalised to the canonical
/// one of ±d (angle in (−90°, 90°]); Indeterminate if d is zero or not finite (a slide along
/// a link whose ends coincide has no direction).
InstantCentre centreAtInfinity(const Eigen::Vector2d& d);

}  // namespace linkwright::kinematics
