#pragma once
// The numbers that define each point of a linkage, as typed parameters: a ground pivot's x
// and y, a crank's length and phase, a driven point's path, an actuator's link length, an RRR
// joint's two lengths, a slider's rod length and its guide, a slotted link's length, a point's offsets on its link, a free point's guess and
// the constraint lengths that reach it. A recognised four-bar (model/recognise.h), however it
// was built or stored, is listed by its named dimensions instead of the raw numbers they stand
// for: frame, crank, coupler and rocker lengths and the frame's direction, set through
// fourbar_dimensions.h. Editors list them, read them and set them through here, so no editor
// touches a point definition itself, and every linkage has one dimensions editor.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/recognise.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// Which number of a point's definition.
enum class ParameterSlot {
  X,                 ///< a ground pivot's x, a free point's guessed x, an arc path's centre x
  Y,                 ///< a ground pivot's y, a free point's guessed y, an arc path's centre y
  Length,            ///< a crank's, a slider's rod's, a slotted link's or an actuator's driven link's
                     ///< length; an RRR's first length; an arc path's radius
  SecondLength,      ///< an RRR's second length
  Phase,             ///< a crank's phase; an arc path's start angle (rad)
  Along,             ///< a point fixed on a link: along it
  Across,            ///< a point fixed on a link: across it
  GuideX,            ///< a slider's guide (a PRP's first): a point on it, x (along its link when on one)
  GuideY,            ///< … y (across its link when on one)
  GuideAngle,        ///< … its angle (rad; from its link's direction when on one)
  SecondGuideX,      ///< a PRP's second guide, as GuideX
  SecondGuideY,      ///< … as GuideY
  SecondGuideAngle,  ///< … as GuideAngle
  ConstraintLength,  ///< the length of Mechanism::constraints[constraint], listed under its later point
  PathX,             ///< a polyline path's vertex `vertex`: x
  PathY,             ///< … y
  Sweep,             ///< an arc path's sweep (rad)
  // A recognised four-bar's named dimensions, derived from the points' numbers; `point` is
  // the point whose definition carries each (O4, B, C, C, O4).
  FrameLength,    ///< a four-bar's O2–O4
  CrankLength,    ///< … O2–B
  CouplerLength,  ///< … B–C
  RockerLength,   ///< … O4–C
  FrameAngle,     ///< … the direction O2→O4 (rad, CCW from +x)
};

/// Whether `slot` is one of a four-bar's named dimensions.
bool isFourBarDimension(ParameterSlot slot);

/// What a parameter's value is: a length (positive), an offset or coordinate (any sign), or
/// an angle (rad).
enum class ParameterUnit { Length, Offset, Angle };

struct Parameter {
  PointId point;
  ParameterSlot slot = ParameterSlot::X;
  std::size_t constraint = 0;  ///< ConstraintLength only
  std::size_t vertex = 0;      ///< PathX and PathY only
  bool operator==(const Parameter&) const = default;
};

/// Every parameter of `mechanism` in the order an editor shows them: point by point; for a
/// four-bar its four named lengths first, then the rest, the frame's direction in place of
/// O4's x and y.
std::vector<Parameter> parametersOf(const Mechanism& mechanism);
/// The same for `mechanism` recognised already (asFourBar with PointsOnLinks::AnyLink).
std::vector<Parameter> parametersOf(const Mechanism& mechanism, const std::optional<FourBarStructure>& fourBar);

/// The kind of value `parameter` holds.
ParameterUnit parameterUnit(ParameterSlot slot);

/// The parameter's value (rad for angles), or nothing if `mechanism` has no such parameter.
std::optional<double> parameterValue(const Mechanism& mechanism, const Parameter& parameter);

/// parameterValue of each of `parameters`, the linkage recognised once for them all (an editor
/// reads every value of a design at each edit).
std::vector<std::optional<double>> parameterValues(const Mechanism& mechanism,
                                                   const std::vector<Parameter>& parameters);
/// The same for `mechanism` recognised already (asFourBar with PointsOnLinks::AnyLink).
std::vector<std::optional<double>> parameterValues(const Mechanism& mechanism, const std::vector<Parameter>& parameters,
                                                   const std::optional<FourBarStructure>& fourBar);

/// Sets the parameter; false (and nothing changed) if `mechanism` has no such parameter. A
/// four-bar's named length keeps O2, the frame's direction, the crank's phase, the branch and
/// a coupler point's place from B (withFourBarLengths). Checking the new value is the
/// design's job (checkDesign).
bool setParameter(Mechanism& mechanism, const Parameter& parameter, double value);

}  // namespace linkwright::kinematics
