#include "kinematics/compare/table_comparison.h"

#include "kinematics/io/number_format.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics::compare {
namespace {

using io::formatShort;

// A row that cannot be solved weighs as much as a deviation of a thousand spans: the fit stays
// where the table's rows assemble.
constexpr double kUnsolvedPenalty = 1e6;

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

// Σ (deviation / scale)² over the fitted columns; unsolved rows weigh kUnsolvedPenalty.
double misfit(const Evaluation& ev, const io::NumericTable& table, const ColumnMapping& mapping,
              const std::vector<bool>& fitted, const std::vector<double>& scale) {
  double sum = 0.0;
  for (std::size_t c = 0; c < mapping.columns.size(); ++c) {
    if (!fitted[c]) continue;
    const MappedColumn& col = mapping.columns[c];
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
      const auto& value = table.rows[r].cells[col.column];
      if (!value) continue;
      if (!ev.exact[c][r]) {
        sum += kUnsolvedPenalty;
        continue;
      }
      const double d = deviationOf(col, *value, *ev.exact[c][r]) / scale[c];
      sum += d * d;
    }
  }
  return sum;
}

struct OffsetFit {
  double offset = 0.0;  // in the input's unit (rad for a crank)
  bool atBound = false;
  bool fromPositions = false;
};

OffsetFit fitOffset(const Mechanism& m, const CompareDrive& drive, const io::NumericTable& table,
                    const ColumnMapping& mapping, double bound) {
  OffsetFit fit;
  std::vector<bool> fitted(mapping.columns.size(), true);
  for (const MappedColumn& c : mapping.columns) fit.fromPositions = fit.fromPositions || isPosition(c);
  for (std::size_t c = 0; c < mapping.columns.size(); ++c)
    fitted[c] = !fit.fromPositions || isPosition(mapping.columns[c]);
  const Evaluation atZero = evaluate(m, drive, table, mapping, 0.0);
  // One scale per dimension, in its sweep unit: the largest span among its columns. Columns of
  // one dimension weigh alike (a degree of θ3 as a degree of θ4, whatever their spans).
  const std::size_t n = mapping.columns.size();
  std::vector<double> dimensionSpan(static_cast<std::size_t>(Dimension::Time) + 1, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const MappedColumn& col = mapping.columns[c];
    double& span = dimensionSpan[static_cast<std::size_t>(col.quantity.dimension)];
    span = std::max(span, spanOf(col, table, atZero.exact[c]) * col.unit.factor);
  }
  std::vector<double> scale(n, 1.0);
  for (std::size_t c = 0; c < n; ++c) {
    const MappedColumn& col = mapping.columns[c];
    const double span = dimensionSpan[static_cast<std::size_t>(col.quantity.dimension)] / col.unit.factor;
    scale[c] = span > 0.0 ? span : std::max(table.rounding[col.column], 1e-12);
  }
  const auto cost = [&](double offset) {
    return misfit(evaluate(m, drive, table, mapping, offset), table, mapping, fitted, scale);
  };
  constexpr int kScan = 100;
  const double step = 2.0 * bound / kScan;
  double best = 0.0, bestCost = cost(0.0);
  for (int i = 0; i <= kScan; ++i) {
    const double offset = -bound + i * step;
    if (const double s = cost(offset); s < bestCost) best = offset, bestCost = s;
  }
  // Golden section on the scan's best interval.
  double a = std::max(-bound, best - step), b = std::min(bound, best + step);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = cost(x1), f2 = cost(x2);
  while (b - a > 1e-9 * std::max(1.0, bound)) {
    if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = cost(x1);
    else a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = cost(x2);
  }
  fit.offset = (a + b) / 2.0;
  if (cost(fit.offset) > bestCost) fit.offset = best;
  fit.atBound = std::abs(fit.offset) > bound - step / 2.0;
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
  if (options.offset == OffsetMode::Auto) {
    const OffsetFit fit = fitOffset(m, drive, table, mapping, toInput(options.offsetBoundDeg));
    offset = fit.offset;
    out.offsetAtBound = fit.atBound;
    out.offsetFromPositions = fit.fromPositions;
  }
  out.offsetDeg = angle ? radToDeg(offset) : offset;
  const Evaluation ev = evaluate(m, drive, table, mapping, offset);
  for (std::size_t c = 0; c < mapping.columns.size(); ++c)
    out.columns.push_back(compareColumn(mapping.columns[c], table, ev, c, out.axis, options));
  return out;
}

}  // namespace linkwright::kinematics::compare
