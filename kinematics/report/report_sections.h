#pragma once
// The pieces report_content.cpp assembles a report from: which sweep columns the report
// tabulates and how their headings read, which plots it draws, the analysis lines (the core's
// analyseDesign, as `linkwright-cli classify` prints it), the drawing at one input, and the
// notes on toggles and inputs that do not assemble.

#include "kinematics/report/report_content.h"
#include "kinematics/solve/sweep_columns.h"

#include <string>
#include <vector>

namespace linkwright::kinematics::report {

/// The heading of a sweep column: "rocker θ" in "deg" or "rad", "C vx" in "mm/s", "rocker ω" in
/// "rad/s" or "deg/s", as `units` says.
TableColumn columnHeading(const Mechanism& mechanism, const kinematics::SweepColumn& column,
                          const ReportUnits& units = {});

/// What a value of `column` (in the sweep column's unit) is multiplied by to be in `units`:
/// 180/π for a link's ω and α in degrees, π/180 for a link or transmission angle in radians,
/// else 1.
double unitScale(const kinematics::SweepColumn& column, const ReportUnits& units);

/// The sweep column's name with its unit as `units` says: "rocker_omega_deg_s",
/// "rocker_angle_rad".
std::string columnName(const kinematics::SweepColumn& column, const ReportUnits& units);

/// The columns a report tabulates, in `analyze`'s CSV order: the time on a time base, the
/// input, each moving link's angle, ω and α but the driven crank's angle (the input) and, on
/// a grid, its ω and α (the grid's constants), the transmission angles and,
/// for slider pins (RRP points), their x, vx, ax (and y, vy, ay where the pin moves in y).
std::vector<kinematics::SweepColumn> reportColumns(const Mechanism& mechanism, const SweepResult& sweep);

/// One plot: its title, its value unit and the column quantities it draws.
struct PlotKind {
  std::string title;
  std::string unit;
  std::vector<kinematics::ColumnQuantity> quantities;
};

/// The report's plots in order: angles, ω, α (in `units`), transmission angle, slider
/// position, velocity and acceleration.
std::vector<PlotKind> plotKinds(const Mechanism& mechanism, const ReportUnits& units = {});

/// An input in the driver's display unit: "30°", "12.5 mm"; `named` prefixes the input's name.
std::string inputText(const Mechanism& mechanism, double input, bool named = true);

/// "Crank angle 0° to 360°, every 30°; crank 1 rad/s, 0 rad/s²" for the grid `spec`, a crank's
/// speed in `rates`.
std::string gridCaption(const Mechanism& mechanism, const SweepSpec& spec, const std::string& sampling,
                        RateUnit rates = RateUnit::Radians);

/// "Time 0 s to 2 s, every 0.1 s; the crank follows its motion law" for the time base `spec`.
std::string timeCaption(const Mechanism& mechanism, const SweepSpec& spec, const std::string& sampling);

/// The Grashof / mobility analysis of `mechanism`, whose sweep over its grid is `gridSweep`.
std::vector<InfoLine> analysisLines(const Mechanism& mechanism, const SweepResult& gridSweep);

/// The linkage drawn at input `at` (the driver's coordinate) with its link lengths; fails,
/// naming "--at", where it cannot be assembled.
Result<ReportDrawing> reportDrawing(const Mechanism& mechanism, double at);

/// Toggles, inputs that do not assemble and locks of `sweep`, one sentence each.
std::vector<std::string> sweepNotes(const Mechanism& mechanism, const SweepResult& sweep);

}  // namespace linkwright::kinematics::report
