#include "ui/plots/compare_overlay.h"

#include "kinematics/model/number_text.h"

#include <QCoreApplication>

#include <cmath>

namespace linkwright::ui {
namespace {

namespace k = kinematics;
namespace kc = kinematics::compare;

QString tr(const char* text) { return QCoreApplication::translate("CompareOverlay", text); }

QString number(double value) { return QString::fromStdString(k::formatShort(value, 4)); }

// A row's place on x: its time on a time axis (only a time table has one), else its input.
std::optional<double> rowX(const kc::Comparison& c, const kc::RowComparison& row, const PlotXAxis& x, AngleUnit unit) {
  if (x.source.axis == PlotAxis::Time) {
    if (c.axis.kind != kc::AxisKind::Time) return std::nullopt;
    return row.x * c.axis.unit.factor;
  }
  if (x.source.input != k::InputKind::Angle) return row.inputDeg;
  double at = toAngleUnit(k::degToRad(row.inputDeg), unit);
  // The sweep's angles are unwrapped: a turn later or earlier may be where the axis is.
  const double turn = toAngleUnit(2.0 * k::kPi, unit);
  if (at < x.range.min || at > x.range.max) at -= std::floor((at - x.range.min) / turn) * turn;
  return at;
}

QString description(const QString& source, const kc::ColumnComparison& column, const kc::RowComparison& row) {
  const QString unit = QString::fromStdString(column.mapped.unit.name);
  const QString line = tr("%1, line %2: %3 %4").arg(source).arg(row.line).arg(number(row.value), unit);
  if (!row.exact) return tr("%1, no exact value: %2").arg(line, QString::fromStdString(row.note));
  const QString verdict = row.flagged ? tr("beyond") : tr("within");
  return tr("%1 against %2 exact: deviation %3, %4 the tolerance ±%5")
      .arg(line, number(*row.exact), number(row.deviation), verdict, number(column.tolerance));
}

}  // namespace

std::vector<OverlayCurve> overlayCurves(const kc::Comparison& comparison, const QString& source,
                                        const std::vector<PlotCurve>& curves, const PlotXAxis& x, AngleUnit unit) {
  std::vector<OverlayCurve> out;
  for (const kc::ColumnComparison& column : comparison.columns) {
    const PlotQuantity quantity{column.mapped.quantity.column.quantity, column.mapped.quantity.column.index};
    const PlotCurve* curve = findCurve(curves, quantity);
    if (curve == nullptr) continue;
    OverlayCurve overlay{quantity, source, {}, {}, {}};
    const bool angular = isAngular(quantityKind(quantity));
    for (const kc::RowComparison& row : column.rows) {
      const std::optional<double> at = rowX(comparison, row, x, unit);
      if (!at) return {};
      const double y = angular ? toAngleUnit(row.restated, unit) : row.restated;
      if (!std::isfinite(*at) || !std::isfinite(y)) continue;
      overlay.points.append(QPointF(*at, y));
      overlay.flagged.append(row.flagged);
      overlay.descriptions.append(description(source, column, row));
    }
    if (!overlay.points.isEmpty()) out.push_back(std::move(overlay));
  }
  return out;
}

}  // namespace linkwright::ui
