#pragma once
// A synthesised four-bar as a mechanism with its ground pivots where the construction put
// them: O2 at `o2`, O4 at `o4`, so the frame may tilt and the crank's input is its absolute
// angle (CCW from +x), which asFourBar (model/recognise.h) reads with its frame angle. Points
// and links are makeFourBar's (O2, O4, B, C, P; crank, coupler, rocker); lengths.frame is not
// used, the frame being |o4 − o2|.

#include "kinematics/model/fourbar.h"

#include <Eigen/Core>

#include <string>

namespace linkwright::kinematics {

Mechanism placedFourBar(const Eigen::Vector2d& o2, const Eigen::Vector2d& o4, const FourBarLengths& lengths,
                        Branch branch, const CouplerPointSpec& couplerPoint, const std::string& lengthUnit);

}  // namespace linkwright::kinematics
