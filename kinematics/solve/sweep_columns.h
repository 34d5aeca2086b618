#pragma once
// The columns a sweep can be tabulated in, each with a name that carries its unit. The CSV
// writer, the CLI's text table and (later) the GUI's plots all pick from this one list, so a
// quantity has the same name and unit everywhere:
//   time_s                             the instant, on a time base (SweepResult::time)
//   crank_angle_deg                    the input angle (the sweep's grid), for a crank driver;
//   <point>_s_<unit>, actuator_length_<unit>   the input of a path or actuator driver
//   <link>_angle_deg                   each moving link other than the driven crank, unwrapped
//   <link>_omega_rad_s, <link>_alpha_rad_s2   each moving link, crank first
//   transmission_angle_deg             per RRR, RRP or actuator dyad (suffixed _<point> when several)
//   <point>_x_<unit>, _y_, _vx_<unit>_s, _vy_, _ax_<unit>_s2, _ay_   each moving point

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"

#include <string>
#include <vector>

namespace linkwright::kinematics {

enum class ColumnQuantity {
  Time,
  InputAngle,
  InputLength,
  LinkAngle,
  LinkOmega,
  LinkAlpha,
  TransmissionAngle,
  PointX,
  PointY,
  PointVx,
  PointVy,
  PointAx,
  PointAy,
};

/// One column: what it holds and of which link or point (`index`).
struct SweepColumn {
  std::string name;  ///< e.g. "rocker_omega_rad_s"
  ColumnQuantity quantity = ColumnQuantity::InputAngle;
  std::size_t index = 0;
  bool operator==(const SweepColumn&) const = default;

  /// True for velocity and acceleration columns: undefined at a toggle position.
  bool isRate() const;
  /// The value at `sample`, in the column's unit (angles in degrees).
  double value(const SweepResult& result, std::size_t sample) const;
  /// The same quantity from a single pose solved at `inputAngle` (rad). Angles are unwrapped
  /// to the turn nearest `nearDeg`, so they compare with the sweep's continuous columns.
  double valueOf(const Pose& pose, double inputAngle, double nearDeg = 0.0) const;
};

/// The unit of a column's quantity, as text: "deg", "rad/s", "rad/s²", "mm", "mm/s", "mm/s²", "s".
/// Angles are in `angleUnit`, a link's ω and α in `rateAngleUnit` per s and per s², lengths and
/// positions in the mechanism's `lengthUnit`; the defaults are the columns' own (angles in
/// degrees, link rates in radians). The one unit rule: the column names, compare's headers,
/// the CLI's tables, the report's headings and the plots' axes all take their unit from here.
std::string columnUnit(ColumnQuantity quantity, const std::string& lengthUnit, const std::string& angleUnit = "deg",
                       const std::string& rateAngleUnit = "rad");

/// A unit as a column's name ends with it: "rad/s²" → "rad_s2", "mm/s" → "mm_s", "deg" → "deg".
std::string unitInName(const std::string& unit);

/// True for the link from the crank pivot to the driven crank tip (zero phase): its angle is
/// the input angle and its ω, α are the driver's.
bool isDrivenCrankLink(const Mechanism& mechanism, LinkId link);

/// All columns available for this mechanism and request, in CSV order; `time_s` first when
/// the sweep ran on a time base.
std::vector<SweepColumn> sweepColumns(const Mechanism& mechanism, const SolveRequest& request, bool timeBase = false);

}  // namespace linkwright::kinematics
