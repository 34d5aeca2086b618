#pragma once
// The plots' x axis: the time (s), on a time base, or the input: a crank's angle (in the plots'
// angle unit) or a linear driver's position (in the length unit), named by the core
// (kinematics/model/driver.h). This is the one place that titles the axis and puts a sample, the
// cursor or a read-out on it, so every chart, marker and read-out agrees.

#include "ui/document/mechanism_document.h"
#include "ui/plots/angle_unit.h"
#include "ui/plots/axis_range.h"

#include "kinematics/analysis/extrema.h"
#include "kinematics/design/design.h"
#include "kinematics/model/driver.h"
#include "kinematics/solve/sweep.h"

#include <QString>

#include <cstddef>
#include <optional>

namespace linkwright::ui {

/// What a sample's x is: its time, or its input (an angle shown in the plots' angle unit, a
/// length shown as it is).
struct XSource {
  PlotAxis axis = PlotAxis::Input;
  kinematics::InputKind input = kinematics::InputKind::Angle;
  bool operator==(const XSource&) const = default;
};

/// The x axis every chart of a design shares.
struct PlotXAxis {
  XSource source;
  AxisRange range;
  QString title;      ///< "time [s]", "crank angle [deg]", "actuator A–C length [m]"
  QString inputName;  ///< the core's name of the input: "crank angle", "tip path position"
  QString inputUnit;  ///< a linear input's length unit; empty for a crank
};

/// What `mechanism`'s input is called: "crank angle", "tip path position", …
QString inputDisplayName(const kinematics::Mechanism& mechanism);
/// The input axis's title: "crank angle [deg]" (in `unit`), "tip path position [m]".
QString inputAxisTitle(const kinematics::Mechanism& mechanism, AngleUnit unit);
/// The time axis's title: "time [s]".
QString timeAxisTitle();
/// Where a read-out says a point is: "crank 90.0°", "crank 1.571 rad", "t = 0.250 s",
/// "tip path position 0.150 m". A default PlotXAxis reads as a crank's.
QString xReadoutText(double x, const PlotXAxis& axis, AngleUnit unit);

/// Sample `j`'s x: its time (s), or its input (unwrapped, as swept) in `unit` for an angle. The
/// input when the sweep has no times.
double sampleX(const kinematics::SweepResult& sweep, std::size_t j, const XSource& x, AngleUnit unit);
/// Where a refined extremum (kinematics/analysis/extrema.h) falls, on the x axis `x` in `unit`.
double extremumX(const kinematics::Extremum& e, const XSource& x, AngleUnit unit);

/// An axis over exactly [lo, hi] (a time span, a linear input's travel), ticks anchored at 0
/// every nice step, about four intervals. An empty span is widened by half a unit each side.
AxisRange exactAxisRange(double lo, double hi);

/// The x axis for `design` swept as `sweep`: its time base's times; or the input over the grid
/// [fromDeg, toDeg] (display units), or on a time base over the inputs the law reaches.
PlotXAxis plotXAxis(const kinematics::Design& design, const kinematics::SweepResult& sweep, PlotAxis axis,
                    AngleUnit unit);

/// Where the cursor goes for the document's motion state on `axis`: the instant, or the input
/// (a crank angle on an angle grid moved by whole turns into it; nullopt if no turn lies there).
std::optional<double> cursorX(const MechanismDocument& document, const PlotXAxis& axis, AngleUnit unit);

}  // namespace linkwright::ui
