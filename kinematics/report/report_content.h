#pragma once
// What a lab report says, as plain values built from core calls: the drawing of the linkage at
// one input with its link lengths, the Grashof / mobility analysis (design_analysis.h, as
// `linkwright-cli classify` prints it), a table of the link angles, ω and α every N degrees
// (every N seconds on a time base; sweep_columns.h, the columns and numbers of `analyze`), the
// refined extremes
// (analysis/column_extrema.h, as `extremes`), the curves of the plots and, when the linkage has masses
// and loads, the joint forces and driving torque (force_sweep.h, as `analyze --forces`).
// Nothing here draws: report_pdf.h lays this out on pages, so a test can check the numbers
// against the solver without reading a PDF. The table step follows the thesis (seed 000),
// which tabulates every 30°.

#include "kinematics/analysis/extrema.h"
#include "kinematics/analysis/link_drawing.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics::report {

/// Digits after the point in the report's tables (as `analyze --format table`).
inline constexpr int kTableDecimals = 4;
/// The most rows a report's table may have (about 200 pages): a smaller step is refused, not
/// printed over thousands of pages.
inline constexpr double kMaxTableRows = 10000;

/// The unit of the link ω and α columns and plots.
enum class RateUnit {
  Radians,  ///< rad/s, rad/s²: the thesis's and `analyze`'s
  Degrees,  ///< deg/s, deg/s²: SolidWorks Motion's, and the designer's plots in degrees
};

/// The unit of the link and transmission angles (the input, the table's x, stays in degrees).
enum class AngleUnit { Degrees, Radians };

/// The units the link angles, ω and α are tabulated and plotted in.
struct ReportUnits {
  AngleUnit angles = AngleUnit::Degrees;  ///< deg (the thesis's, analyze's) or rad
  RateUnit rates = RateUnit::Radians;     ///< rad/s, rad/s² (the thesis's) or deg/s, deg/s² (SolidWorks')
  bool operator==(const ReportUnits&) const = default;
};

/// What to report on and how.
struct ReportRequest {
  std::string title;     ///< the heading: the document's file name or the example's name
  std::string subtitle;  ///< what it is (the example's description); may be empty
  std::string date;      ///< as printed, e.g. "2026-11-26"
  /// The plots' and extremes' sweep (the document's grid: its range, step, ω and α), or its
  /// time base (a motion law in time): then the table has a time column and the plots and
  /// extremes are against time.
  SweepSpec grid;
  /// The table's step in the driver's coordinate (rad for a crank, the length unit for a
  /// linear driver), or in seconds on a time base, > 0; the table runs from the grid's start
  /// to its end.
  double tableStep = 0.0;
  /// The drawn pose's input, in the driver's coordinate; on a time base its time (s), within
  /// the time span.
  double drawAt = 0.0;
  ReportUnits units;
};

/// A column of a report table: its heading and its unit ("rocker θ", "deg").
struct TableColumn {
  std::string heading;
  std::string unit;
};

/// A table as printed: the cells' text and the numbers behind them.
struct ReportTable {
  std::vector<TableColumn> columns;
  std::vector<std::vector<std::string>> cells;             ///< rows × columns, as printed
  std::vector<std::vector<std::optional<double>>> values;  ///< the same; nullopt for text and undefined cells
};

/// A label: "Grashof class", "crank-rocker (shortest link: crank, longest: coupler)".
struct InfoLine {
  std::string label;
  std::string text;
};

/// One curve of a plot, broken where the quantity is undefined (toggles, unassembled inputs).
struct PlotCurve {
  std::string label;
  std::vector<std::vector<Eigen::Vector2d>> segments;  ///< (input, value) runs
};

/// A line plot of one kind of quantity against the input.
struct ReportPlot {
  std::string title;   ///< "Angular velocity ω"
  std::string xTitle;  ///< "crank angle (deg)"
  std::string yTitle;  ///< "rad/s"
  std::vector<PlotCurve> curves;
};

/// A dimension of the drawing: a link's length, written along it.
struct Dimension {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  std::string text;     ///< "crank 25 mm"
  bool ground = false;  ///< between two ground pivots: drawn as a dimension line under them
};

/// The linkage at the drawn input.
struct ReportDrawing {
  kinematics::LinkDrawing parts;  ///< plates, holes and ground crosses, as the DXF export draws them
  std::vector<Dimension> dimensions;
  std::vector<Eigen::Vector2d> groundPivots;
  std::vector<std::pair<Eigen::Vector2d, std::string>> pointLabels;  ///< each point's name at its position
  std::string caption;                                               ///< "at crank angle 0°"
};

/// Everything a report shows, in order.
struct ReportContent {
  std::string title;
  std::string subtitle;
  std::string date;
  ReportDrawing drawing;
  std::vector<InfoLine> analysis;  ///< Grashof class, mobility, ranges, limits, time ratio
  std::string tableCaption;
  ReportTable table;
  std::string extremesCaption;
  ReportTable extremes;  ///< quantity, minimum, where, maximum, where
  std::vector<ReportPlot> plots;
  std::string forcesCaption;
  std::optional<ReportTable> forces;  ///< when the linkage has masses and loads
  std::vector<std::string> notes;     ///< toggles, inputs that do not assemble, locks
};

/// The heading of a report, one rule for the CLI's `report` and the designer's Report ▸ PDF:
/// the title is `name`, what the linkage goes by (the document's file name, the example's
/// name); the subtitle says what it is, the example's `description`, else the design's `kind`,
/// and is left empty when it would only repeat the title (a new four-bar's report is headed
/// "four-bar", not "four-bar" over "four-bar").
void setReportHeading(ReportRequest& request, const std::string& name, const std::string& description,
                      const std::string& kind);

/// The report of `mechanism` (a valid one) with `dynamics` (may be empty). Fails, naming the
/// field, on a time base, a table step that is not positive and finite, an input that cannot
/// be assembled at `drawAt`, or forces that cannot be solved (a length unit forces cannot
/// convert).
Result<ReportContent> buildReport(const Mechanism& mechanism, const LinkageDynamics& dynamics,
                                  const ReportRequest& request);

}  // namespace linkwright::kinematics::report
