#include "kinematics/compare/compare_quantity.h"

#include "kinematics/model/validate.h"

#include "kinematics/model/units.h"

namespace linkwright::kinematics::compare {
namespace {

using kinematics::ColumnQuantity;

struct Shape {
  Dimension dimension;
  std::string suffix;  // the sweep column's unit suffix
};

Dimension dimensionOf(ColumnQuantity q) {
  switch (q) {
  case ColumnQuantity::InputAngle:
  case ColumnQuantity::LinkAngle:
  case ColumnQuantity::TransmissionAngle: return Dimension::Angle;
  case ColumnQuantity::LinkOmega: return Dimension::AngularRate;
  case ColumnQuantity::LinkAlpha: return Dimension::AngularAcceleration;
  case ColumnQuantity::InputLength:
  case ColumnQuantity::PointX:
  case ColumnQuantity::PointY: return Dimension::Length;
  case ColumnQuantity::PointVx:
  case ColumnQuantity::PointVy: return Dimension::Velocity;
  case ColumnQuantity::PointAx:
  case ColumnQuantity::PointAy: return Dimension::Acceleration;
  case ColumnQuantity::Time: break;
  }
  return Dimension::Time;
}

// The suffix is the sweep column's own (sweep_columns.h: columnUnit).
Shape shapeOf(ColumnQuantity q, const std::string& u) {
  return {dimensionOf(q), "_" + kinematics::unitInName(kinematics::columnUnit(q, u))};
}

// "rad/s^2", "rad/s²", "deg/sec**2" → "rad/s2", "deg/s2".
std::string normalised(std::string name) {
  const std::pair<std::string, std::string> replacements[] = {{"²", "2"}, {"^2", "2"}, {"**2", "2"}, {"/sec", "/s"}};
  for (const auto& [from, to] : replacements)
    for (std::size_t at = name.find(from); at != std::string::npos; at = name.find(from, at))
      name.replace(at, from.size(), to);
  return name;
}

std::vector<UnitChoice> lengthUnits(const std::string& lengthUnit, const std::string& per) {
  std::vector<UnitChoice> units{{lengthUnit + per, 1.0}};
  const auto own = metresPerLengthUnit(lengthUnit);
  if (!own) return units;
  for (const char* name : {"m", "cm", "mm", "in", "ft"})
    if (name != lengthUnit) units.push_back({name + per, *metresPerLengthUnit(name) / *own});
  return units;
}

}  // namespace

std::vector<CompareQuantity> compareQuantities(const Mechanism& m) {
  std::vector<CompareQuantity> quantities;
  for (const kinematics::SweepColumn& column : kinematics::sweepColumns(m, SolveRequest{true, true})) {
    if (column.quantity == ColumnQuantity::Time) continue;
    const Shape shape = shapeOf(column.quantity, m.lengthUnit);
    std::string key = column.name;
    if (key.size() > shape.suffix.size() && key.ends_with(shape.suffix)) key.resize(key.size() - shape.suffix.size());
    quantities.push_back({key, column, shape.dimension});
  }
  return quantities;
}

std::optional<CompareQuantity> findQuantity(const Mechanism& m, const std::string& key, std::string* impliedUnit) {
  for (const CompareQuantity& q : compareQuantities(m)) {
    if (q.key == key) return q;
    if (q.column.name == key) {
      if (impliedUnit) *impliedUnit = unitsFor(q.dimension, m.lengthUnit).front().name;
      return q;
    }
  }
  return std::nullopt;
}

std::vector<UnitChoice> unitsFor(Dimension dimension, const std::string& lengthUnit) {
  constexpr double kDeg = kPi / 180.0;
  switch (dimension) {
  case Dimension::Angle: return {{"deg", 1.0}, {"rad", 180.0 / kPi}};
  case Dimension::AngularRate: return {{"rad/s", 1.0}, {"deg/s", kDeg}, {"rpm", 2.0 * kPi / 60.0}};
  case Dimension::AngularAcceleration: return {{"rad/s2", 1.0}, {"deg/s2", kDeg}};
  case Dimension::Length: return lengthUnits(lengthUnit, "");
  case Dimension::Velocity: return lengthUnits(lengthUnit, "/s");
  case Dimension::Acceleration: return lengthUnits(lengthUnit, "/s2");
  case Dimension::Time: return {{"s", 1.0}, {"ms", 1e-3}, {"min", 60.0}};
  }
  return {};
}

std::optional<UnitChoice> findUnit(Dimension dimension, const std::string& lengthUnit, const std::string& name) {
  const std::string wanted = normalised(name);
  for (const UnitChoice& unit : unitsFor(dimension, lengthUnit))
    if (unit.name == wanted) return unit;
  return std::nullopt;
}

std::string unitList(Dimension dimension, const std::string& lengthUnit) {
  std::string list;
  for (const UnitChoice& unit : unitsFor(dimension, lengthUnit)) list += (list.empty() ? "" : ", ") + unit.name;
  return list;
}

double largestMagnitude(Dimension dimension) {
  constexpr double lever = kMaxLengthRatio;
  switch (dimension) {
  case Dimension::Angle: return kMaxAngleDeg;
  case Dimension::AngularRate: return kMaxOmega * lever;
  case Dimension::AngularAcceleration: return kMaxAlpha * lever * lever;
  case Dimension::Length: return kMaxLength;
  case Dimension::Velocity: return kMaxLength * kMaxOmega;
  case Dimension::Acceleration: return kMaxLength * kMaxAlpha;
  case Dimension::Time: return 1e9;
  }
  return kMaxLength;
}

const char* dimensionName(Dimension dimension) {
  switch (dimension) {
  case Dimension::Angle: return "angle";
  case Dimension::AngularRate: return "angular velocity";
  case Dimension::AngularAcceleration: return "angular acceleration";
  case Dimension::Length: return "length";
  case Dimension::Velocity: return "velocity";
  case Dimension::Acceleration: return "acceleration";
  case Dimension::Time: return "time";
  }
  return "quantity";
}

}  // namespace linkwright::kinematics::compare
