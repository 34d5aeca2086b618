#include "kinematics/compare/table_comparison.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/golden_section.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics::compare {
namespace {

using kinematics::formatShort;

// The exact values of every mapped column at every row, for one offset.
struct Evaluation {
  std::vector<std::vector<std::optional<double>>> exact;  // [column][row], the file's form
  std::vector<std::vector<double>> swept;                 // [column][row], the sweep column's form
  std::vector<std::string> notes;                         // [row]: why rates or the pose are missing
  std::vector<double> inputDeg;                           // [row]
};

DriverState driverAt(const CompareDrive& d, const AxisColumn& axis, double x, double offset) {
  if (axis.kind == AxisKind::CrankAngle) return {degToRad(x * axis.unit.factor) + offset, d.omega, d.alpha};
  const double t = x * axis.unit.factor;
  if (d.law) {
    DriverState s = motionAt(*d.law, t);
    s.position += offset;
    return s;
  }
  return {d.startAngle + d.omega * t + 0.5 * d.alpha * t * t + offset, d.omega + d.alpha * t, d.alpha};
}

bool isAngle(const MappedColumn& c) { return c.quantity.dimension == Dimension::Angle && !c.magnitude; }

// The exact value `e` (as the sweep column states it) as the file's column states it: its
// unit, its end of the link, its sign, |·|.
double fileForm(const MappedColumn& c, double e) {
  if (c.reversed) e += 180.0;
  if (c.negated) e = -e;
  if (c.magnitude) e = std::abs(e);
  return e / c.unit.factor;
}

// value − exact; an angle's across the nearest turn (in the column's unit).
double deviationOf(const MappedColumn& c, double value, double exact) {
  if (!isAngle(c)) return value - exact;
  return std::remainder(value - exact, 360.0 / c.unit.factor);
}

Evaluation evaluate(const Mechanism& m, const CompareDrive& drive, const io::NumericTable& table,
                    const ColumnMapping& mapping, double offset) {
  Evaluation ev;
  const std::size_t rows = table.rows.size();
  ev.exact.assign(mapping.columns.size(), std::vector<std::optional<double>>(rows));
  ev.swept.assign(mapping.columns.size(), std::vector<double>(rows, 0.0));
  ev.notes.assign(rows, std::string());
  ev.inputDeg.assign(rows, 0.0);
  const bool angle = inputKind(m) == InputKind::Angle;
  Pose pose;
  preparePose(m, pose);
  for (std::size_t r = 0; r < rows; ++r) {
    const DriverState state = driverAt(drive, *mapping.axis, *table.rows[r].cells[mapping.axis->column], offset);
    ev.inputDeg[r] = angle ? radToDeg(state.position) : state.position;
    const PoseReport report = solvePoseInto(m, state, SolveRequest{true, true}, pose);
    if (report.status != PoseStatus::Ok) ev.notes[r] = describeFailure(m, report, pose, state.position);
    if (report.status == PoseStatus::NotAssemblable) continue;
    for (std::size_t c = 0; c < mapping.columns.size(); ++c) {
      const MappedColumn& col = mapping.columns[c];
      if (report.status == PoseStatus::Singular && col.quantity.column.isRate()) continue;
      ev.swept[c][r] = col.quantity.column.valueOf(pose, state.position);
      ev.exact[c][r] = fileForm(col, ev.swept[c][r]);
    }
  }
  return ev;
}

bool isPosition(const MappedColumn& c) {
  return c.quantity.dimension == Dimension::Angle || c.quantity.dimension == Dimension::Length;
}

double spanOf(const MappedColumn& c, const io::NumericTable& table, const std::vector<std::optional<double>>& exact) {
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (std::size_t r = 0; r < exact.size(); ++r) {
    const auto& value = table.rows[r].cells[c.column];
    if (!exact[r] || !value) continue;
    // An angle's exact value on the turn of the file's value, so a span never jumps by 360°.
    const double e = *value - deviationOf(c, *value, *exact[r]);
    lo = any ? std::min(lo, e) : e;
    hi = any ? std::max(hi, e) : e;
    any = true;
  }
  return hi - lo;
}

// The offset fit weighs each cell (row, fitted column) by its column's default tolerance:
// u = deviation / (rounding + 0.25 % of the span at δ = 0). A cell beyond kInlierBound
// tolerances is one the comparison should flag, not one the offset should explain.
constexpr double kInlierBound = 3.0;
// An offset replaces zero only when it at least halves the misfit: a table's rounding noise
// lets a fitted δ take off a few per cent, never half (1/N of it on average, N cells).
constexpr double kClearlyBetter = 0.5;

struct FitCells {
  const io::NumericTable& table;
  const ColumnMapping& mapping;
  std::vector<bool> fitted;       // [column]
  std::vector<double> tolerance;  // [column]
};

// u of every cell with a value in a fitted column: nullopt where the pose has no exact value.
template <typename Visit>
void forEachCell(const FitCells& cells, const Evaluation& ev, Visit visit) {
  for (std::size_t c = 0; c < cells.mapping.columns.size(); ++c) {
    if (!cells.fitted[c]) continue;
    const MappedColumn& col = cells.mapping.columns[c];
    for (std::size_t r = 0; r < cells.table.rows.size(); ++r) {
      const auto& value = cells.table.rows[r].cells[col.column];
      if (!value) continue;
      if (!ev.exact[c][r]) visit(c, r, std::optional<double>());
      else visit(c, r, std::optional<double>(deviationOf(col, *value, *ev.exact[c][r]) / cells.tolerance[c]));
    }
  }
}

// Σ min(u², K²): a cell that disagrees (or cannot be solved) costs K² wherever δ is, so it
// cannot pull the fit. Scanned over the whole bound, this finds the offset most rows agree on.
double robustMisfit(const FitCells& cells, const Evaluation& ev) {
  double sum = 0.0;
  forEachCell(cells, ev, [&](std::size_t, std::size_t, std::optional<double> u) {
    sum += u ? std::min(*u * *u, kInlierBound * kInlierBound) : kInlierBound * kInlierBound;
  });
  return sum;
}

using CellSet = std::vector<std::vector<bool>>;  // [column][row]: the fit uses the cell

CellSet inliers(const FitCells& cells, const Evaluation& ev) {
  CellSet set(cells.mapping.columns.size(), std::vector<bool>(cells.table.rows.size(), false));
  forEachCell(cells, ev, [&](std::size_t c, std::size_t r, std::optional<double> u) {
    set[c][r] = u && std::abs(*u) <= kInlierBound;
  });
  return set;
}

// Σ u² over `set`; a cell of the set that can no longer be solved costs K².
double squares(const FitCells& cells, const Evaluation& ev, const CellSet& set) {
  double sum = 0.0;
  forEachCell(cells, ev, [&](std::size_t c, std::size_t r, std::optional<double> u) {
    if (set[c][r]) sum += u ? *u * *u : kInlierBound * kInlierBound;
  });
  return sum;
}

// The minimum of `cost` on [a, b] by golden section, to 1e-9 of the bound.
template <typename Cost>
double offsetMinimum(const Cost& cost, double a, double b, double bound) {
  return goldenSectionMinimum(cost, a, b, 1e-9 * std::max(1.0, bound)).middle();
}

struct OffsetFit {
  double offset = 0.0;  // in the input's unit (rad for a crank)
  bool atBound = false;
  bool fromPositions = false;
  bool keptZero = false;          // a fitted offset did not explain the rows clearly better than none
  CellSet used;                   // the cells the fit was made on (of the rows it was made on)
  std::vector<bool> fitted;       // [column]
  std::vector<double> tolerance;  // [column]: a cell's unit of misfit
};

// The offset is one number: a few thousand rows spread over the table fix it as well as a
// million, and the fit solves its rows about 140 times. A longer table is fitted on every k-th
// row, and solved whole once at the offset found.
constexpr std::size_t kFitRows = 4096;

// Every k-th row of `table`, at most kFitRows, or nothing if the table is no longer.
std::optional<io::NumericTable> fitSample(const io::NumericTable& table) {
  if (table.rows.size() <= kFitRows) return std::nullopt;
  io::NumericTable sample = table;
  sample.rows.clear();
  const std::size_t every = (table.rows.size() + kFitRows - 1) / kFitRows;
  for (std::size_t r = 0; r < table.rows.size(); r += every) sample.rows.push_back(table.rows[r]);
  return sample;
}

// Iteratively trimmed least squares: the robust scan's best δ, then least squares on the cells
// within kInlierBound tolerances of it, repeated until those cells stay the same; zero unless
// that δ at least halves the misfit of those cells.
OffsetFit fitOffset(const Mechanism& m, const CompareDrive& drive, const io::NumericTable& table,
                    const ColumnMapping& mapping, double bound) {
  OffsetFit fit;
  const std::size_t n = mapping.columns.size();
  FitCells cells{table, mapping, std::vector<bool>(n, true), std::vector<double>(n, 1.0)};
  for (const MappedColumn& c : mapping.columns) fit.fromPositions = fit.fromPositions || isPosition(c);
  for (std::size_t c = 0; c < n; ++c) cells.fitted[c] = !fit.fromPositions || isPosition(mapping.columns[c]);
  const Evaluation atZero = evaluate(m, drive, table, mapping, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const MappedColumn& col = mapping.columns[c];
    const double t =
        table.rounding[col.column] + CompareOptions{}.relativeTolerance * spanOf(col, table, atZero.exact[c]);
    cells.tolerance[c] = std::max(t, 1e-12);
  }
  const auto at = [&](double offset) { return evaluate(m, drive, table, mapping, offset); };

  constexpr int kScan = 100;
  const double step = 2.0 * bound / kScan;
  double best = 0.0, bestCost = robustMisfit(cells, atZero);
  for (int i = 0; i <= kScan; ++i) {
    const double offset = -bound + i * step;
    if (const double s = robustMisfit(cells, at(offset)); s < bestCost) best = offset, bestCost = s;
  }
  double offset = offsetMinimum([&](double d) { return robustMisfit(cells, at(d)); }, std::max(-bound, best - step),
                                std::min(bound, best + step), bound);
  if (robustMisfit(cells, at(offset)) > bestCost) offset = best;

  CellSet used = inliers(cells, at(offset));
  for (int round = 0; round < 10; ++round) {
    const auto cost = [&](double d) { return squares(cells, at(d), used); };
    const double refined = offsetMinimum(cost, std::max(-bound, offset - step), std::min(bound, offset + step), bound);
    if (cost(refined) <= cost(offset)) offset = refined;
    CellSet next = inliers(cells, at(offset));
    if (next == used) break;
    used = std::move(next);
  }
  if (!(squares(cells, at(offset), used) <= kClearlyBetter * squares(cells, atZero, used))) {
    fit.keptZero = offset != 0.0;
    offset = 0.0;
    used = inliers(cells, atZero);
  }
  fit.offset = offset;
  fit.atBound = std::abs(offset) > bound - step / 2.0;
  fit.used = std::move(used);
  fit.fitted = std::move(cells.fitted);
  fit.tolerance = std::move(cells.tolerance);
  return fit;
}

std::optional<Error> checkOptions(const Mechanism& m, const CompareDrive& drive, const ColumnMapping& mapping,
                                  const CompareOptions& o) {
  const auto bad = [](const std::string& field, const std::string& why) {
    return Error{ErrorCode::InvalidValue, field, why};
  };
  if (!(o.offsetBoundDeg > 0.0 && o.offsetBoundDeg <= 90.0))
    return bad("offset", "the offset bound must be in (0, 90] degrees (got " + formatShort(o.offsetBoundDeg) + ")");
  if (o.offset == OffsetMode::Given && !(std::abs(o.offsetDeg) <= o.offsetBoundDeg))
    return bad("offset", "the offset must be within ±" + formatShort(o.offsetBoundDeg) + "° (got " +
                             formatShort(o.offsetDeg) + ")");
  if (!(o.relativeTolerance >= 0.0 && o.relativeTolerance <= 1.0))
    return bad("tolerance", "the relative tolerance must be between 0 and 100 % of the span (got " +
                                formatShort(o.relativeTolerance * 100.0) + " %)");
  if (o.absoluteTolerance && !(std::isfinite(*o.absoluteTolerance) && *o.absoluteTolerance >= 0.0))
    return bad("tolerance", "the absolute tolerance must be zero or positive and finite (got " +
                                formatShort(*o.absoluteTolerance) + ")");
  if (mapping.axis && mapping.axis->kind == AxisKind::CrankAngle) {
    if (inputKind(m) != InputKind::Angle)
      return bad("drive", "this linkage's input is a length, not a crank angle: map a time column instead");
    if (drive.law)
      return bad("drive",
                 "this linkage's crank follows a motion law in time, so a crank angle does not give its "
                 "speed: map a time column instead");
  }
  return std::nullopt;
}

// The file's `value` as the solver states the quantity (radians for an angle, the sweep
// column's unit otherwise, our sign, from the link's first joint); `swept` is the exact value
// as the sweep column states it, whose sign a magnitude takes, or empty.
double restate(const MappedColumn& c, double value, double deviation, std::optional<double> swept) {
  const double toSolver = c.quantity.dimension == Dimension::Angle ? degToRad(1.0) : 1.0;
  if (swept) {
    // The deviation carried over to our sign keeps an angle on the exact value's turn.
    const double sign = c.magnitude ? (*swept < 0.0 ? -1.0 : 1.0) : (c.negated ? -1.0 : 1.0);
    return (*swept + sign * deviation * c.unit.factor) * toSolver;
  }
  double v = value * c.unit.factor;
  if (c.negated) v = -v;
  if (c.reversed) v -= 180.0;
  return v * toSolver;
}

ColumnComparison compareColumn(const MappedColumn& col, const io::NumericTable& table, const Evaluation& ev,
                               std::size_t c, const AxisColumn& axis, const CompareOptions& o) {
  ColumnComparison out;
  out.mapped = col;
  out.label = table.labels[col.column];
  out.span = spanOf(col, table, ev.exact[c]);
  out.tolerance = o.absoluteTolerance.value_or(table.rounding[col.column]) + o.relativeTolerance * out.span;
  double squares = 0.0;
  std::size_t withExact = 0;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const io::NumericRow& row = table.rows[r];
    if (!row.cells[col.column]) continue;
    RowComparison rc;
    rc.line = row.line;
    rc.x = *row.cells[axis.column];
    rc.inputDeg = ev.inputDeg[r];
    rc.value = *row.cells[col.column];
    ++out.compared;
    if (ev.exact[c][r]) {
      rc.deviation = deviationOf(col, rc.value, *ev.exact[c][r]);
      rc.exact = rc.value - rc.deviation;
      rc.flagged = std::abs(rc.deviation) > out.tolerance;
      rc.restated = restate(col, rc.value, rc.deviation, ev.swept[c][r]);
      squares += rc.deviation * rc.deviation;
      ++withExact;
      if (std::abs(rc.deviation) > std::abs(out.worst)) out.worst = rc.deviation, out.worstX = rc.x;
    } else {
      rc.flagged = true;
      rc.note = ev.notes[r];
      rc.restated = restate(col, rc.value, 0.0, std::nullopt);
    }
    out.flagged += rc.flagged ? 1 : 0;
    out.rows.push_back(std::move(rc));
  }
  out.rms = withExact > 0 ? std::sqrt(squares / static_cast<double>(withExact)) : 0.0;
  return out;
}

}  // namespace

CompareDrive compareDriveFor(const Design& design) {
  CompareDrive drive;
  drive.omega = design.omega;
  drive.alpha = design.alpha;
  drive.startAngle = inputKind(design.mechanism) == InputKind::Angle ? degToRad(design.fromDeg) : design.fromDeg;
  if (design.time) drive.law = design.time->law;
  return drive;
}

std::size_t Comparison::flaggedRows() const {
  std::size_t n = 0;
  for (const ColumnComparison& c : columns) n += c.flagged;
  return n;
}

Result<Comparison> compareTable(const Mechanism& m, const CompareDrive& drive, const io::NumericTable& table,
                                const ColumnMapping& mapping, const CompareOptions& options) {
  if (auto e = checkMechanism(m)) return *e;
  if (auto e = checkColumnMapping(mapping, table)) return *e;
  if (auto e = checkOptions(m, drive, mapping, options)) return *e;
  const bool angle = inputKind(m) == InputKind::Angle;
  const auto toInput = [angle](double deg) { return angle ? degToRad(deg) : deg; };
  Comparison out;
  out.axis = *mapping.axis;
  out.offsetMode = options.offset;
  double offset = options.offset == OffsetMode::Given ? toInput(options.offsetDeg) : 0.0;
  OffsetFit fit;
  const std::optional<io::NumericTable> sample = options.offset == OffsetMode::Auto ? fitSample(table) : std::nullopt;
  if (options.offset == OffsetMode::Auto) {
    fit = fitOffset(m, drive, sample ? *sample : table, mapping, toInput(options.offsetBoundDeg));
    offset = fit.offset;
    out.offsetAtBound = fit.atBound;
    out.offsetFromPositions = fit.fromPositions;
    out.offsetKeptZero = fit.keptZero;
  }
  out.offsetDeg = angle ? radToDeg(offset) : offset;
  const Evaluation ev = evaluate(m, drive, table, mapping, offset);
  // Fitted on a sample: the cells left out are those of every row beyond the bound at the offset.
  if (sample) fit.used = inliers(FitCells{table, mapping, fit.fitted, fit.tolerance}, ev);
  for (std::size_t c = 0; c < mapping.columns.size(); ++c) {
    ColumnComparison column = compareColumn(mapping.columns[c], table, ev, c, out.axis, options);
    const bool fitted = options.offset == OffsetMode::Auto && (!fit.fromPositions || isPosition(column.mapped));
    for (std::size_t r = 0, k = 0; r < table.rows.size(); ++r) {
      if (!table.rows[r].cells[column.mapped.column]) continue;
      column.rows[k++].outsideFit = fitted && !fit.used[c][r];
    }
    out.columns.push_back(std::move(column));
  }
  return out;
}

}  // namespace linkwright::kinematics::compare
