#pragma once
// The numbers that define each point of a linkage, as editable fields: a ground pivot's x and
// y, a crank's length and phase, an RRR joint's two lengths, a slider's rod length and its
// guide, a slotted link's length, a point's offsets on its link, a free point's guess and the
// constraint lengths that reach it. The dimensions panel shows one editor per field; reading
// and writing go through here, so the panel never touches a point definition itself.

#include "kinematics/model/mechanism.h"

#include <QString>

#include <vector>

namespace linkwright::ui {

enum class FieldKind {
  Length,    ///< positive, length unit
  Offset,    ///< any sign, length unit (offsets, coordinates)
  AngleDeg,  ///< degrees in the editor, radians in the model
};

struct DimensionField {
  kinematics::PointId point;
  int slot = 0;  ///< which number of the point's definition (see dimension_fields.cpp)
  FieldKind kind = FieldKind::Length;
  QString label;  ///< "to O₂", "x", "phase", "guide angle"
  bool operator==(const DimensionField&) const = default;
};

/// Every editable number of `mechanism`, point by point.
std::vector<DimensionField> dimensionFields(const kinematics::Mechanism& mechanism);

/// The field's value as the editor shows it (degrees for angles).
double fieldValue(const kinematics::Mechanism& mechanism, const DimensionField& field);

/// Sets the field to `value` (degrees for angles) in `mechanism`.
void setFieldValue(kinematics::Mechanism& mechanism, const DimensionField& field, double value);

/// The RRR or RRP joint's branch, if the point has one.
kinematics::Branch* branchOf(kinematics::Point& point);
const kinematics::Branch* branchOf(const kinematics::Point& point);

/// What a point is, for the panel's heading: "crank tip", "RRR joint", "slider", ...
QString pointRole(const kinematics::Mechanism& mechanism, kinematics::PointId point);

}  // namespace linkwright::ui
