#pragma once
// What Edit ▸ Attach dyad… asks the core to do, as a value the dialog fills and the tests
// build directly: the dyad's kind, its new joint's name, its parents (existing points, or a
// new point on a link or a new ground pivot, added first), its lengths, guides and branch.
// Suggestions pre-fill a request from the current pose so that it assembles there: the
// parents' positions come from the core's pose solver, the lengths from their distances.

#include "kinematics/design/design.h"
#include "kinematics/model/attach_dyad.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <string>

namespace linkwright::kinematics {

enum class DyadKind { Rrr, Rrp, Rpr, Prp };

/// A parent of the new dyad.
struct ParentChoice {
  enum class Source { Existing, OnLink, NewGround };
  Source source = Source::Existing;
  PointId point;                                       ///< Existing
  LinkId link;                                         ///< OnLink
  double along = 0.0;                                  ///< OnLink, length unit
  double across = 0.0;                                 ///< OnLink, length unit
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< NewGround, length unit
};

struct DyadRequest {
  DyadKind kind = DyadKind::Rrr;
  std::string joint;          ///< the new joint's name
  ParentChoice first;         ///< RRR: first parent; RRP: the rod's other end; RPR: the pivot
  ParentChoice second;        ///< RRR: second parent; RPR: the point the slot passes through
  double firstLength = 1.0;   ///< RRR: to first; RRP: the rod; RPR: the slotted link
  double secondLength = 1.0;  ///< RRR: to second
  Guide guide;                ///< RRP: the slider's guide; PRP: the first guide
  Guide secondGuide;          ///< PRP: the second guide
  Branch branch = Branch::Open;
};

/// Adds the new parents, then the dyad. An Error (the core's) names what is wrong; the input
/// mechanism is never changed.
Result<Mechanism> applyDyadRequest(const Mechanism& mechanism, const DyadRequest& request);

/// `design` with the dyad attached; its kind becomes "linkage", since it is no longer the
/// textbook mechanism it was.
Result<Design> attachToDesign(const Design& design, const DyadRequest& request);

/// A request of `kind` for `mechanism` at `crankAngle` (rad): parents picked from its last
/// points, a fresh joint name, lengths from fillLengths.
DyadRequest suggestDyad(const Mechanism& mechanism, double crankAngle, DyadKind kind);

/// Sets the request's lengths from the distances between its parents at `crankAngle`, so that
/// it assembles there: an RRR's links three quarters of the parents' distance each, an RRP's
/// rod longer than its end's distance from the guide, an RPR's slotted link past the point it
/// slides through. Leaves them as they are if the parents cannot be placed.
void fillLengths(const Mechanism& mechanism, double crankAngle, DyadRequest& request);

/// A point name not used in `mechanism`: the next free letter from E (skipping O), or "O<n>"
/// for a ground pivot.
std::string freshPointName(const Mechanism& mechanism, bool groundPivot = false);

}  // namespace linkwright::kinematics
