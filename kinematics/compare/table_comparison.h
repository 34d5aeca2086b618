#pragma once
// Another tool's table against the exact solution: each mapped column's deviation from the
// exact value at the table's own inputs (the pose solved at each row's crank angle or time,
// never interpolated from a sweep), its worst and rms deviation, and the rows beyond a
// tolerance flagged.
//
// Crank-angle offset. A motion study often starts a hair away from the angle it claims (the
// thesis's SolidWorks export, seed 000 Figures 41–43, is at −0.106°). The table's row at x is
// then solved at x + δ, with δ constant. With OffsetMode::Auto, δ is fitted robustly, so that
// the rows a comparison should flag (a typo, a wrong formula) cannot pull it:
//   1. each cell's deviation is measured in its column's default tolerance (rounding + 0.25 %
//      of the span), u = deviation / tolerance, and Σ min(u², 3²) is scanned on 101 points
//      over |δ| ≤ the bound and refined by golden section: a cell beyond 3 tolerances costs
//      the same wherever δ is;
//   2. least squares on the cells within 3 tolerances of that δ (golden section to 1e-9 of
//      the bound), repeated until those cells stay the same: iteratively trimmed;
//   3. zero is kept unless the fitted δ at least halves Σ u² over those cells: rounding noise
//      lets a fit take off about 1/N of it (N cells), an offset in the table nearly all.
// The cells left out are marked (RowComparison::outsideFit). Position columns (angles,
// coordinates) decide δ when any are mapped: they are what an offset shifts first.
//
// Tolerance. A row is flagged when |deviation| > absolute + relative × span: by default the
// absolute part is the column's own rounding (half a unit in its last printed digit) and the
// relative part 0.25 % of the span. On the thesis's tables (tests/kinematics/compare/) the
// Excel α4 typo's smallest error, 0.0152 rad/s² at 270° (0.53 % of the span), is flagged
// against 0.005 + 0.0072; SolidWorks' sampling error after the offset, at most 0.22 deg/s²
// in α4 (0.19 % of the span), and the two-decimal rounding pass.

#include "kinematics/compare/column_mapping.h"
#include "kinematics/design/design.h"
#include "kinematics/io/numeric_table_csv.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/motion_law.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics::compare {

/// How the driver moves at the table's inputs.
struct CompareDrive {
  double omega = 1.0;            ///< rad/s: the crank's speed at every crank angle, and of a time table
  double alpha = 0.0;            ///< rad/s²
  double startAngle = 0.0;       ///< rad: the crank angle at t = 0 of a time table without a law
  std::optional<MotionLaw> law;  ///< a document's motion law: a time table follows it
};

/// The drive of a design: its crank's speed and acceleration, its grid's first angle as the
/// angle at t = 0, and its motion law if it has a time base.
CompareDrive compareDriveFor(const Design& design);

/// Whether a constant crank-angle offset is removed.
enum class OffsetMode { Auto, None, Given };

/// The comparison's settings; the defaults are those the CLI and the dialog start from.
struct CompareOptions {
  OffsetMode offset = OffsetMode::Auto;
  double offsetDeg = 0.0;                   ///< OffsetMode::Given: the offset, degrees, within the bound
  double offsetBoundDeg = 5.0;              ///< Auto searches |δ| ≤ this, degrees, (0, 90]
  double relativeTolerance = 0.0025;        ///< fraction of the column's span, [0, 1]
  std::optional<double> absoluteTolerance;  ///< in each column's unit, ≥ 0; default: its rounding
};

/// One row of one column.
struct RowComparison {
  int line = 0;                 ///< the file's line
  double x = 0.0;               ///< the row's x as the file gives it
  double inputDeg = 0.0;        ///< the crank angle solved at (offset included), degrees
  double value = 0.0;           ///< the file's value
  std::optional<double> exact;  ///< the exact value as the file states it (unit, sign, |·|); empty where none exists
  double deviation = 0.0;       ///< value − exact (angles: the nearest turn); 0 without an exact value
  bool flagged = false;         ///< beyond the tolerance, or no exact value
  /// The file's value as the solver states the quantity, to draw over the exact curve: radians
  /// for an angle (rad/s, rad/s² and the length unit as the sweep columns), our sign, from the
  /// link's first joint, an angle on the exact value's turn, and a magnitude with the exact
  /// value's sign (its own where there is none).
  double restated = 0.0;
  std::string note;         ///< why there is no exact value (cannot be assembled, a toggle)
  bool outsideFit = false;  ///< OffsetMode::Auto: the offset fit left this cell out (beyond 3 tolerances)
};

/// One mapped column's deviations.
struct ColumnComparison {
  MappedColumn mapped;
  std::string label;         ///< the file's header for the column
  double span = 0.0;         ///< max − min of the exact values over the rows, the column's unit
  double tolerance = 0.0;    ///< absolute + relative × span, the column's unit
  double worst = 0.0;        ///< the largest |deviation|, signed
  double worstX = 0.0;       ///< the x of that row
  double rms = 0.0;          ///< root mean square deviation over the rows with a value and an exact one
  std::size_t compared = 0;  ///< rows with a value (empty cells are skipped)
  std::size_t flagged = 0;
  std::vector<RowComparison> rows;
};

/// The whole comparison.
struct Comparison {
  AxisColumn axis;
  OffsetMode offsetMode = OffsetMode::Auto;
  double offsetDeg = 0.0;            ///< δ used: rows solved at x + δ
  bool offsetAtBound = false;        ///< Auto's δ is at the bound: the true offset may be larger
  bool offsetFromPositions = false;  ///< Auto fitted δ to the position columns only
  bool offsetKeptZero = false;       ///< Auto kept δ = 0: no offset halved the misfit
  std::vector<ColumnComparison> columns;
  std::size_t flaggedRows() const;  ///< over all columns
};

/// Compares `table` under `mapping` with the exact solution of `mechanism` driven as `drive`.
/// An Error (field "map", "offset", "tolerance" or "drive") for a mapping that does not fit the
/// table, an option out of range, or a crank-angle table for a linkage whose input follows a
/// motion law or is a length. Rows the linkage cannot be assembled at are flagged, not errors.
Result<Comparison> compareTable(const Mechanism& mechanism, const CompareDrive& drive, const io::NumericTable& table,
                                const ColumnMapping& mapping, const CompareOptions& options = {});

}  // namespace linkwright::kinematics::compare
