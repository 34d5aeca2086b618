#include "kinematics/solve/sweep_columns.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <cmath>

namespace linkwright::kinematics {
namespace {

// The end of a column's name for its quantity's unit: "_deg", "_rad_s", "_mm_s2".
std::string unitEnding(ColumnQuantity q, const std::string& lengthUnit) {
  return "_" + unitInName(columnUnit(q, lengthUnit));
}

// The input's column: the crank angle in degrees, named for the driven link, whose own angle
// column it replaces ("crank_angle_deg"; "rocker_angle_deg" for a four-bar driven from its
// rocker), or the linear driver's coordinate, named for its point ("tip_s_m") or actuator
// ("actuator_length_mm").
SweepColumn inputColumn(const Mechanism& m) {
  if (inputKind(m) == InputKind::Angle) {
    const std::string ending = unitEnding(ColumnQuantity::InputAngle, m.lengthUnit);
    for (std::size_t k = 0; k < m.links.size(); ++k)
      if (isDrivenCrankLink(m, LinkId{k})) return {m.links[k].name + "_angle" + ending, ColumnQuantity::InputAngle, 0};
    return {"crank_angle" + ending, ColumnQuantity::InputAngle, 0};
  }
  const auto driver = driverPoint(m);
  const std::string ending = unitEnding(ColumnQuantity::InputLength, m.lengthUnit);
  if (driver && std::holds_alternative<ActuatorPoint>(m.points[driver->index].definition))
    return {"actuator_length" + ending, ColumnQuantity::InputLength, 0};
  return {(driver ? m.points[driver->index].name : std::string("input")) + "_s" + ending, ColumnQuantity::InputLength,
          0};
}

}  // namespace

std::string columnUnit(ColumnQuantity q, const std::string& lengthUnit, const std::string& angleUnit,
                       const std::string& rateAngleUnit) {
  switch (q) {
  case ColumnQuantity::Time: return "s";
  case ColumnQuantity::InputAngle:
  case ColumnQuantity::LinkAngle:
  case ColumnQuantity::TransmissionAngle: return angleUnit;
  case ColumnQuantity::LinkOmega: return rateAngleUnit + "/s";
  case ColumnQuantity::LinkAlpha: return rateAngleUnit + "/s²";
  case ColumnQuantity::InputLength:
  case ColumnQuantity::PointX:
  case ColumnQuantity::PointY: return lengthUnit;
  case ColumnQuantity::PointVx:
  case ColumnQuantity::PointVy: return lengthUnit + "/s";
  case ColumnQuantity::PointAx:
  case ColumnQuantity::PointAy: return lengthUnit + "/s²";
  }
  return lengthUnit;
}

std::string unitInName(const std::string& unit) {
  std::string name;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    if (unit[i] == '/') name += '_';
    else if (unit.compare(i, 2, "²") == 0) name += '2', ++i;
    else name += unit[i];
  }
  return name;
}

bool isDrivenCrankLink(const Mechanism& m, LinkId id) {
  const Link& link = m.links[id.index];
  const auto* crank = std::get_if<CrankPoint>(&m.points[link.second.index].definition);
  return crank != nullptr && crank->pivot == link.first && crank->phase == 0.0;
}

bool SweepColumn::isRate() const {
  switch (quantity) {
  case ColumnQuantity::LinkOmega:
  case ColumnQuantity::LinkAlpha:
  case ColumnQuantity::PointVx:
  case ColumnQuantity::PointVy:
  case ColumnQuantity::PointAx:
  case ColumnQuantity::PointAy: return true;
  default: return false;
  }
}

double SweepColumn::value(const SweepResult& r, std::size_t j) const {
  switch (quantity) {
  case ColumnQuantity::Time: return r.time[j];
  case ColumnQuantity::InputAngle: return radToDeg(r.inputAngle[j]);
  case ColumnQuantity::InputLength: return r.inputAngle[j];
  case ColumnQuantity::LinkAngle: return radToDeg(r.linkAngle[index][j]);
  case ColumnQuantity::LinkOmega: return r.linkOmega[index][j];
  case ColumnQuantity::LinkAlpha: return r.linkAlpha[index][j];
  case ColumnQuantity::TransmissionAngle: return radToDeg(r.transmissionAngle[index][j]);
  case ColumnQuantity::PointX: return r.position[index][j].x();
  case ColumnQuantity::PointY: return r.position[index][j].y();
  case ColumnQuantity::PointVx: return r.velocity[index][j].x();
  case ColumnQuantity::PointVy: return r.velocity[index][j].y();
  case ColumnQuantity::PointAx: return r.acceleration[index][j].x();
  case ColumnQuantity::PointAy: return r.acceleration[index][j].y();
  }
  return 0.0;
}

double SweepColumn::valueOf(const Pose& p, double inputAngle, double nearDeg) const {
  const auto unwrapped = [&](double deg) { return nearDeg + std::remainder(deg - nearDeg, 360.0); };
  switch (quantity) {
  case ColumnQuantity::Time: return 0.0;  // not a property of the pose
  case ColumnQuantity::InputAngle: return radToDeg(inputAngle);
  case ColumnQuantity::InputLength: return inputAngle;
  case ColumnQuantity::LinkAngle: return unwrapped(radToDeg(p.linkAngle[index]));
  case ColumnQuantity::LinkOmega: return p.linkOmega[index];
  case ColumnQuantity::LinkAlpha: return p.linkAlpha[index];
  case ColumnQuantity::TransmissionAngle: return radToDeg(p.transmissionAngle[index]);
  case ColumnQuantity::PointX: return p.position[index].x();
  case ColumnQuantity::PointY: return p.position[index].y();
  case ColumnQuantity::PointVx: return p.velocity[index].x();
  case ColumnQuantity::PointVy: return p.velocity[index].y();
  case ColumnQuantity::PointAx: return p.acceleration[index].x();
  case ColumnQuantity::PointAy: return p.acceleration[index].y();
  }
  return 0.0;
}

std::vector<SweepColumn> sweepColumns(const Mechanism& m, const SolveRequest& request, bool timeBase) {
  using Q = ColumnQuantity;
  const bool vel = request.velocities || request.accelerations;
  const bool acc = request.accelerations;
  std::vector<SweepColumn> columns;
  const std::string& u = m.lengthUnit;
  if (timeBase) columns.push_back({"time" + unitEnding(Q::Time, u), Q::Time, 0});
  columns.push_back(inputColumn(m));
  for (std::size_t k = 0; k < m.links.size(); ++k) {
    const std::string& name = m.links[k].name;
    if (!isDrivenCrankLink(m, LinkId{k}))
      columns.push_back({name + "_angle" + unitEnding(Q::LinkAngle, u), Q::LinkAngle, k});
    if (vel) columns.push_back({name + "_omega" + unitEnding(Q::LinkOmega, u), Q::LinkOmega, k});
    if (acc) columns.push_back({name + "_alpha" + unitEnding(Q::LinkAlpha, u), Q::LinkAlpha, k});
  }
  const std::vector<std::size_t> joints = transmissionJoints(m);
  for (const std::size_t i : joints)
    columns.push_back(
        {(joints.size() > 1 ? "transmission_angle_" + m.points[i].name : std::string("transmission_angle")) +
             unitEnding(Q::TransmissionAngle, u),
         Q::TransmissionAngle, i});
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (std::holds_alternative<GroundPoint>(m.points[i].definition)) continue;
    const std::string& p = m.points[i].name;
    columns.push_back({p + "_x" + unitEnding(Q::PointX, u), Q::PointX, i});
    columns.push_back({p + "_y" + unitEnding(Q::PointY, u), Q::PointY, i});
    if (vel) {
      columns.push_back({p + "_vx" + unitEnding(Q::PointVx, u), Q::PointVx, i});
      columns.push_back({p + "_vy" + unitEnding(Q::PointVy, u), Q::PointVy, i});
    }
    if (acc) {
      columns.push_back({p + "_ax" + unitEnding(Q::PointAx, u), Q::PointAx, i});
      columns.push_back({p + "_ay" + unitEnding(Q::PointAy, u), Q::PointAy, i});
    }
  }
  return columns;
}

}  // namespace linkwright::kinematics
