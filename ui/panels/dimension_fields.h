#pragma once
// The dimensions panel's fields: the core's parameters of each point
// (kinematics/design/parameters.h) with their labels, and their values as the editors show
// them (degrees for angles). The panel never touches a point definition itself.

#include "kinematics/design/design.h"
#include "kinematics/design/parameters.h"
#include "kinematics/model/mechanism.h"

#include <QString>

#include <vector>

namespace linkwright::ui {

/// One editor of the dimensions panel: a core parameter (kinematics/design/parameters.h)
/// and its label.
struct DimensionField {
  kinematics::Parameter parameter;
  QString label;  ///< "to O₂", "x", "phase", "guide angle"
  bool operator==(const DimensionField&) const = default;

  kinematics::PointId point() const { return parameter.point; }
  kinematics::ParameterUnit unit() const { return kinematics::parameterUnit(parameter.slot); }
};

/// Every editable number of `mechanism`, point by point.
std::vector<DimensionField> dimensionFields(const kinematics::Mechanism& mechanism);
/// The same for `mechanism` recognised already (asFourBar with PointsOnLinks::AnyLink).
std::vector<DimensionField> dimensionFields(const kinematics::Mechanism& mechanism,
                                            const std::optional<kinematics::FourBarStructure>& fourBar);

/// The fields' values as the editor shows them (degrees for angles), the linkage recognised
/// once for them all.
std::vector<double> fieldValues(const kinematics::Mechanism& mechanism, const std::vector<DimensionField>& fields,
                                const std::optional<kinematics::FourBarStructure>& fourBar);

/// Sets the field to `value` (degrees for angles) in `design`, as the core sets a design's
/// parameter (a driven path's new end included: kinematics/design/design_parameter.h).
void setFieldValue(kinematics::Design& design, const DimensionField& field, double value);

/// The RRR or RRP joint's branch, if the point has one.
kinematics::Branch* branchOf(kinematics::Point& point);
const kinematics::Branch* branchOf(const kinematics::Point& point);

/// What a point is, for the panel's heading: "crank tip", "RRR joint", "slider", ...
QString pointRole(const kinematics::Mechanism& mechanism, kinematics::PointId point);

}  // namespace linkwright::ui
