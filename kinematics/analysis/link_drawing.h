#pragma once
// A linkage's parts as a workshop drawing at true size, at one pose: what the DXF export
// (dxf_export.h) writes. The parts are the rigid bodies that rigid_bodies.h finds from the
// point definitions (a binary link, a ternary plate merged from constraint triangles, a slider
// block), so a plate is one piece however many Links and constraints describe it. Each body
// gets one layer, named after it (its first link's name, "body3", "slider_C"):
//
//   Rigid body: its outline is the convex hull of circles of radius w/2 (w the plate width)
//     around every point fixed on it; two points give a stadium (obround), three or more a
//     plate of tangent lines and arcs. Every point on it gets a hole of diameter d.
//   Slotted link (RPR): as above, plus a slot of width d on the line from its pivot to its tip,
//     from one web (w/2 − d/2) past the pivot's hole to one web short of the tip's hole,
//     stretched to the block's pin where the drawn pose puts it further out. The slot is not
//     swept over a cycle: a pin that travels beyond it at other inputs is not drawn.
//   Slider block: a w × 2w rectangle centred on its pin, its long side along the line it
//     slides on, with the pin's hole.
//   Ground (layer GROUND): each ground pivot as a hole of diameter d with a centre cross w
//     long. Guides, paths and actuators are not drawn.
//
// Outlines are closed polylines with bulges (DXF's LWPOLYLINE convention): the edge from a
// vertex to the next is an arc of sweep θ with bulge tan(θ/4), positive counter-clockwise, or
// straight with bulge 0. Lengths in the mechanism's length unit; x right, y up.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// What the drawing is made with (length unit). Left empty, the hole diameter is a fifth of
/// the shortest distance between two points on one moving body, to two significant digits,
/// and the plate width twice the hole diameter.
struct DrawingOptions {
  std::optional<double> holeDiameter;  ///< > 0 and < the shortest distance between two points on one body
  std::optional<double> plateWidth;    ///< > the hole diameter
  bool operator==(const DrawingOptions&) const = default;
};

/// One vertex of a closed outline; `bulge` describes the edge to the next vertex.
struct OutlineVertex {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double bulge = 0.0;  ///< tan(θ/4) of the arc to the next vertex (θ > 0 counter-clockwise); 0 straight
  bool operator==(const OutlineVertex&) const = default;
};

/// A closed outline: the last vertex joins the first.
using Outline = std::vector<OutlineVertex>;

/// A round hole centred on a point of the mechanism.
struct Hole {
  PointId point;                                     ///< the point it is drilled for
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< the point's position at the pose
  double diameter = 0.0;
  bool operator==(const Hole&) const = default;
};

/// A straight line (a ground pivot's cross).
struct DrawingLine {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  bool operator==(const DrawingLine&) const = default;
};

/// One part on its own layer.
struct DrawingLayer {
  std::string name;               ///< DXF-legal, unique ignoring case (dxfLayerName)
  std::vector<Outline> outlines;  ///< the part's outline first, then slots
  std::vector<Hole> holes;
  std::vector<DrawingLine> lines;
  bool operator==(const DrawingLayer&) const = default;
};

/// The whole drawing: GROUND first, then the rigid bodies, then the slider blocks.
struct LinkDrawing {
  std::string lengthUnit;     ///< the mechanism's
  double holeDiameter = 0.0;  ///< as used (length unit)
  double plateWidth = 0.0;    ///< as used (length unit)
  std::vector<DrawingLayer> layers;
  bool operator==(const LinkDrawing&) const = default;
};

/// The shortest distance between two points fixed on one moving rigid body at `pose` (length
/// unit): holes must be smaller. Fails as bodiesOf does.
Result<double> shortestJointSpacing(const Mechanism& mechanism, const Pose& pose);

/// The drawing of `mechanism` at `pose` (an assembled pose of it). Fails, naming the field
/// ("holeDiameter", "plateWidth"), the value and the accepted range, on a hole that is not
/// positive and finite or not smaller than shortestJointSpacing, a plate no wider than the
/// hole, a pose that is not assembled, or a structure bodiesOf refuses.
Result<LinkDrawing> linkDrawing(const Mechanism& mechanism, const Pose& pose, const DrawingOptions& options);

/// The outline of circles of `radius` around `centres` (their convex hull, counter-clockwise,
/// arcs as bulges); two centres give a stadium, one a circle as two half arcs.
Outline roundedHull(const std::vector<Eigen::Vector2d>& centres, double radius);

/// `name` as a DXF layer name: letters, digits, '_', '-' and '$' kept, anything else '_';
/// empty → "PART".
std::string dxfLayerName(const std::string& name);

}  // namespace linkwright::kinematics
