#pragma once
// The part of a mechanism one request needs. A Selection (pose.h) names the points and links
// to report; every point is defined from earlier points (and links), so the points to solve
// are the selected ones plus everything they are defined from, found in one backward pass
// over the ordered point list. A group of free points is solved whole, with the earlier
// points its constraints reach. The sweep builds a scope once and the pose solver skips
// whatever lies outside it: the cost of a sweep follows what the scene shows.
//
// The scope also lists, once, the points and links the solver runs and which link is the
// driven crank, so a sweep's samples run straight down those lists instead of testing every
// point and link of the mechanism each time.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// A link the solver computes. `crankPhase` is set when the link is the driven crank (from its
/// pivot to its tip, or the reverse): its angle is then the input angle plus this, exactly.
struct LinkStep {
  LinkId link;
  std::optional<double> crankPhase;  ///< rad
};

struct SolveScope {
  std::vector<unsigned char> solvePoint;   ///< per point: 1 if the solver computes it
  std::vector<unsigned char> solveLink;    ///< per link: 1 if its angle (and rates) are computed
  std::vector<unsigned char> reportPoint;  ///< per point: 1 if selected (a result column)
  std::vector<unsigned char> reportLink;   ///< per link: 1 if selected
  /// The points solved, in order; a free group by its first point. Not the ground pivots:
  /// preparePose places them, and they never move.
  std::vector<PointId> pointSteps;
  std::vector<LinkStep> linkSteps;  ///< the links solved, in order
};

/// The crank phase of link k if it is the driven crank (see LinkStep), else nullopt. Inline:
/// a pose solved without a scope asks it of every link.
inline std::optional<double> crankPhaseOf(const Mechanism& m, LinkId k) {
  const Link& l = m.links[k.index];
  const auto* c = std::get_if<CrankPoint>(&m.points[l.second.index].definition);
  if (c != nullptr && c->pivot == l.first) return c->phase;
  const auto* reversed = std::get_if<CrankPoint>(&m.points[l.first.index].definition);
  if (reversed != nullptr && reversed->pivot == l.second) return reversed->phase + kPi;
  return std::nullopt;
}

/// Error naming the entry ("only.points[2]") whose id the mechanism does not have.
std::optional<Error> checkSelection(const Mechanism& mechanism, const Selection& selection);

/// The scope of a valid selection on a valid mechanism (checkMechanism, checkSelection).
SolveScope scopeOf(const Mechanism& mechanism, const Selection& selection);

}  // namespace linkwright::kinematics
