#pragma once
// The numbers an optimisation of a linkage may change, and how far: the design's dimensions
// exactly as the tolerance analyses list them (tune/tolerance_dimensions.h: every length and
// coordinate, a four-bar by its named lengths and O4 across the frame line), so there is one
// parameterisation of a linkage. Each gets a range:
//   a length (ParameterUnit::Length, and a four-bar's named lengths): [v(1 − r), v(1 + r)],
//     r the fraction the user gives (default 0.5), so it stays positive;
//   a coordinate or an offset (a pivot's x or y, a point's place on its link, a guide's point,
//     O4 across the frame line): v ± r·S, S the linkage's size (its longest length dimension),
//     since a coordinate's own value says nothing about how far it may go;
//   or a range the user gives by the dimension's name, [lo, hi] in the length unit, which must
//     hold the start.
// A fixed ground pivot keeps every number that places it: its x and y, and for a four-bar's O4
// the frame length and O4 across the frame line. By default every ground pivot is fixed (a
// redesign keeps its mounting holes); the user may free any of them.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/tune/tolerance_dimensions.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// The default ± on each length, as a fraction of its start.
inline constexpr double kDefaultLengthRange = 0.5;
/// The largest ± accepted, as a fraction (a length must stay positive).
inline constexpr double kMaxLengthRange = 0.95;

/// A range the user gives one dimension, by its name (ToleranceDimension::name).
struct DimensionRange {
  std::string name;  ///< "crank length", "P along its link", …
  double lo = 0.0;   ///< length unit
  double hi = 0.0;   ///< length unit, ≥ lo
  bool operator==(const DimensionRange&) const = default;
};

/// What the optimisation must keep.
struct OptimiseConstraints {
  double lengthRange = kDefaultLengthRange;  ///< r: ± on each length as a fraction, in (0, 0.95]
  std::vector<DimensionRange> ranges;        ///< replace r's range for the dimensions they name
  /// The ground pivots held where they are, by name; nothing: every ground point.
  std::optional<std::vector<std::string>> fixedPivots;
  bool operator==(const OptimiseConstraints&) const = default;
};

/// One dimension the optimisation reads, with its range.
struct OptimiseDimension {
  ToleranceDimension dimension;  ///< its name and its start value (length unit)
  double lo = 0.0;               ///< length unit; lo == hi == start when fixed
  double hi = 0.0;               ///< length unit
  bool fixed = false;            ///< it places a fixed pivot
  bool operator==(const OptimiseDimension&) const = default;
};

/// The dimensions of `mechanism` (checkMechanism passed) with their ranges. Error naming the
/// field: "lengthRange" out of (0, 0.95]; "fixedPivots[1]" not a ground point's name;
/// "ranges[0].name" no such dimension, "ranges[0]" lo > hi or not finite, a length's lo ≤ 0,
/// or the start outside it; "dimensions" when nothing is left to change.
Result<std::vector<OptimiseDimension>> optimiseDimensions(const Mechanism& mechanism,
                                                          const OptimiseConstraints& constraints);

/// The mechanism with each free dimension at `values[d]` (length unit, the same order as
/// `dimensions`; fixed ones are left at their start).
Mechanism withDimensionValues(const Mechanism& start, const std::vector<OptimiseDimension>& dimensions,
                              const std::vector<double>& values);

}  // namespace linkwright::kinematics
