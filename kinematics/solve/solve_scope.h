#pragma once
// The part of a mechanism one request needs. A Selection (pose.h) names the points and links
// to report; every point is defined from earlier points (and links), so the points to solve
// are the selected ones plus everything they are defined from, found in one backward pass
// over the ordered point list. A group of free points is solved whole, with the earlier
// points its constraints reach. The sweep builds a scope once and the pose solver skips
// whatever lies outside it: the cost of a sweep follows what the scene shows.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

struct SolveScope {
  std::vector<unsigned char> solvePoint;   ///< per point: 1 if the solver computes it
  std::vector<unsigned char> solveLink;    ///< per link: 1 if its angle (and rates) are computed
  std::vector<unsigned char> reportPoint;  ///< per point: 1 if selected (a result column)
  std::vector<unsigned char> reportLink;   ///< per link: 1 if selected
};

/// Error naming the entry ("only.points[2]") whose id the mechanism does not have.
std::optional<Error> checkSelection(const Mechanism& mechanism, const Selection& selection);

/// The scope of a valid selection on a valid mechanism (checkMechanism, checkSelection).
SolveScope scopeOf(const Mechanism& mechanism, const Selection& selection);

} // namespace linkwright::kinematics
