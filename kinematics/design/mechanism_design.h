#pragma once
// What a user designs and saves when the linkage is not a plain four-bar: the mechanism itself
// (points, links, constraints: a slider-crank, a shaper, a six-bar, anything built from
// dyads or free points), how its crank is driven and the grid it is analysed on. A four-bar
// keeps its parametric FourBarDesign (design.h: Grashof class, exact ranges, length drags);
// Design holds either, so the GUI, the CLI and the document file handle both the same way.

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <string>
#include <variant>

namespace linkwright::kinematics {

struct MechanismDesign {
  std::string kind = "linkage";  ///< what it is, shown to the user: "slider-crank", "watt-ii", …
  Mechanism mechanism;
  double omega = 1.0;         ///< crank, rad/s (CCW positive)
  double alpha = 0.0;         ///< crank, rad/s²
  double fromDeg = 0.0;       ///< analysis grid start, degrees
  double toDeg = 360.0;       ///< analysis grid end, degrees
  std::size_t samples = 721;  ///< grid points from fromDeg to toDeg inclusive (≥ 2)
  LinkageDynamics dynamics;   ///< masses and loads for forces, by link and point name; empty: none
  bool operator==(const MechanismDesign&) const = default;
};

/// A four-bar (parametric) or any other linkage.
using Design = std::variant<FourBarDesign, MechanismDesign>;

/// Error naming the first invalid field: the mechanism's ("points[3].firstLength"), the
/// driver's and grid's ("omega", "samples", …) as for a four-bar design, or the dynamics'
/// ("dynamics.links[0].mass").
std::optional<Error> checkDesign(const MechanismDesign& design);
std::optional<Error> checkDesign(const Design& design);

/// The solver's mechanism for a valid design.
Result<Mechanism> buildMechanism(const Design& design);

/// The design's analysis grid at its crank speed.
SweepSpec designSweepSpec(const MechanismDesign& design);
SweepSpec designSweepSpec(const Design& design);

/// The length unit of either kind of design.
const std::string& designLengthUnit(const Design& design);

/// A built-in example as a design, sampled every 0.5° over its range.
MechanismDesign designFromExample(const MechanismExample& example);

/// The built-in example named `name` (four-bar or not) as a design, if there is one.
std::optional<Design> designForExample(const std::string& name);

}  // namespace linkwright::kinematics
