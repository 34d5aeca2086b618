#pragma once
// What the canvas draws for a mechanism, read off its structure (never its numbers): which
// links are plain bars, which carry points and so are drawn as plates (ternary bodies), which
// are slotted (RPR), where the sliders sit on which guides, which ground pivots the dashed
// frame joins, which points are driven along which paths, which actuators and two-link
// workspaces to draw, which points get a handle, a traced path or a rate arrow, and which points a
// label should keep clear of. Two mechanisms with the same plan differ only in dimensions, so
// the scene keeps its items and just moves them.

#include "kinematics/model/mechanism.h"

#include <QString>

#include <cstddef>
#include <vector>

namespace linkwright::ui {

/// A link plus the points fixed on it: drawn as a filled plate over its corners.
struct BodyShape {
  kinematics::LinkId link;
  std::vector<kinematics::PointId> corners;  ///< the link's two points, then the attached ones
  bool operator==(const BodyShape&) const = default;
};

/// A slider block on a guide: the joint of an RRP dyad (guide 0), or one of the two blocks of
/// a PRP pin (guide 0 and guide 1).
struct SliderShape {
  kinematics::PointId joint;
  int guide = 0;            ///< which guide of the joint's definition
  std::size_t ordinal = 0;  ///< the slider's number, for its colour
  bool onGround = true;     ///< a ground guide is drawn as a hatched slideway
  bool operator==(const SliderShape&) const = default;
};

/// A slotted link (RPR): it turns about `pivot`, its slot slides on a block pinned at
/// `through`, its tip is `tip`.
struct SlotShape {
  kinematics::LinkId link;
  kinematics::PointId pivot;
  kinematics::PointId through;
  kinematics::PointId tip;
  bool operator==(const SlotShape&) const = default;
};

/// A pair of points to join with a line: frame lines between ground pivots, or distance
/// constraints (free points) that no link draws already.
struct PointPair {
  kinematics::PointId first;
  kinematics::PointId second;
  bool operator==(const PointPair&) const = default;
};

/// A linear actuator (a cylinder) from its base pin to its end.
struct ActuatorShape {
  kinematics::PointId base;
  kinematics::PointId end;
  bool operator==(const ActuatorShape&) const = default;
};

/// Two links from a ground pivot to a point driven along a path (a two-link arm): the joint
/// between them can only be assembled while the driven point is inside their workspace.
struct WorkspaceShape {
  kinematics::PointId pivot;
  kinematics::PointId joint;
  kinematics::PointId driven;
  bool operator==(const WorkspaceShape&) const = default;
};

struct DrawingPlan {
  std::vector<bool> barLinks;  ///< per link: drawn as a plain bar (not slotted)
  std::vector<BodyShape> bodies;
  std::vector<SliderShape> sliders;
  std::vector<SlotShape> slottedLinks;
  std::vector<PointPair> frameLines;
  std::vector<PointPair> constraintBars;
  std::vector<kinematics::PointId> drivenPaths;  ///< points driven along a path: their paths are drawn
  std::vector<std::size_t> pathVertices;         ///< per driven path: its vertices' handles (0 for an arc)
  std::vector<ActuatorShape> actuators;
  std::vector<WorkspaceShape> workspaces;
  std::vector<bool> ground;                                  ///< per point: a ground pivot
  std::vector<bool> draggable;                               ///< per point: has a drag handle (all but PRP pins)
  std::vector<bool> traced;                                  ///< per point: its path over the cycle is drawn
  std::vector<bool> attached;                                ///< per point: fixed on a link (drawn as a dot)
  std::vector<std::vector<kinematics::PointId>> neighbours;  ///< per point: what it is joined to
  bool operator==(const DrawingPlan&) const = default;
};

/// The plan for `mechanism` (assumed valid).
DrawingPlan planDrawing(const kinematics::Mechanism& mechanism);

/// The guide a slider shape sits on.
const kinematics::Guide& sliderGuide(const kinematics::Mechanism& mechanism, const SliderShape& slider);

/// The crank tip's definition, if the mechanism has one (it always should).
const kinematics::CrankPoint* crankOf(const kinematics::Mechanism& mechanism);

/// A point's name as the canvas writes it: a letter followed by digits gets subscript digits
/// ("O2" → "O₂", "J5" → "J₅"); other names unchanged.
QString pointDisplayName(const std::string& name);

}  // namespace linkwright::ui
