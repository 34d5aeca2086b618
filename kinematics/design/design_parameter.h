#pragma once
// Setting one of a design's parameters (parameters.h) as an editor does, with what the edit
// means for the drive: a point driven along a path whose grid or time base ran to the path's
// end runs to its new end when the path is lengthened or shortened. Without it, an arm whose
// path grew from 0.424 m to 0.68 m was analysed over its first 0.424 m only.

#include "kinematics/design/design.h"
#include "kinematics/design/parameters.h"

namespace linkwright::kinematics {

/// setParameter on the design's mechanism; false if the parameter does not exist there. When
/// it changes the length of the driven point's path and the analysis grid (toDeg, in the
/// length unit) or the time base (the law's position at toTime) reached the old path's end to
/// 1e-9 of its length, that end moves to the new path's end: toDeg becomes the new length, and
/// toTime the first instant the law reaches it (kept if the law never does).
bool setDesignParameter(Design& design, const Parameter& parameter, double value);

}  // namespace linkwright::kinematics
