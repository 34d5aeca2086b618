#pragma once
// Growing a linkage by dyads, the way a designer builds a six-bar from a four-bar: pick points
// on existing links (or new ground pivots), then attach a dyad (RRR, RRP, RPR or PRP) whose new
// joint and links are appended to the Mechanism. Every function returns a new, checked
// Mechanism (or the Error that names the field) and leaves its input untouched, so the GUI can
// offer it as one undoable edit.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <string>
#include <variant>

namespace linkwright::kinematics {

/// Adds a point fixed on `link` (along its direction, across it 90° CCW, from its first point).
Result<Mechanism> addPointOnLink(const Mechanism& mechanism, const std::string& name, LinkId link, double along,
                                 double across);

/// Adds a ground pivot at `position` (length unit).
Result<Mechanism> addGroundPivot(const Mechanism& mechanism, const std::string& name, const Eigen::Vector2d& position);

/// RRR: joint `joint` at `firstLength` from `first` and `secondLength` from `second`; adds the
/// links first→joint and second→joint.
struct RrrDyadSpec {
  std::string joint;
  PointId first;
  double firstLength = 1.0;
  PointId second;
  double secondLength = 1.0;
  Branch branch = Branch::Open;
};

/// RRP: a slider `joint` at `length` from `first` on `guide`; adds the rod first→joint.
struct RrpDyadSpec {
  std::string joint;
  PointId first;
  double length = 1.0;
  Guide guide;
  Branch branch = Branch::Open;
};

/// RPR: a slotted link turning about `pivot` whose slot passes through `through`; its tip
/// `joint` is at `length` from the pivot; adds the slotted link pivot→joint.
struct RprDyadSpec {
  std::string joint;
  PointId pivot;
  PointId through;
  double length = 1.0;
};

/// PRP: the pin `joint` of two sliders, one on each guide; adds no rigid link.
struct PrpDyadSpec {
  std::string joint;
  Guide first;
  Guide second;
};

using DyadSpec = std::variant<RrrDyadSpec, RrpDyadSpec, RprDyadSpec, PrpDyadSpec>;

/// Appends the dyad's joint and links (named link5, link6, … in textbook numbering, the frame
/// being link 1) and checks the result. Assembly is not checked here: solve a pose for that.
Result<Mechanism> attachDyad(const Mechanism& mechanism, const DyadSpec& dyad);

}  // namespace linkwright::kinematics
