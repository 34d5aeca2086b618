#pragma once
// Another tool's table drawn over the plots (File ▸ Compare…): each compared column's rows as
// markers on the chart of its quantity, at the crank angle (or time) each row was solved at,
// with the file's value restated as the solver states the quantity
// (kinematics/compare/table_comparison.h), in the plots' units. A row that agrees lies on the
// exact curve; a row beyond the tolerance is marked as such.

#include "ui/plots/angle_unit.h"
#include "ui/plots/plot_quantity.h"
#include "ui/plots/plot_x_axis.h"

#include "kinematics/compare/table_comparison.h"

#include <QList>
#include <QPointF>
#include <QString>

#include <vector>

namespace linkwright::ui {

/// One compared column as markers on its quantity's chart.
struct OverlayCurve {
  PlotQuantity quantity;
  QString name;                 ///< legend: the file's name ("thesis_excel_table7")
  QList<QPointF> points;        ///< plot units, in the file's row order
  QList<bool> flagged;          ///< per point: beyond the tolerance, or no exact value
  QList<QString> descriptions;  ///< per point, for the read-out: the file's line, value, exact value
  bool operator==(const OverlayCurve&) const = default;
};

/// The markers of `comparison` on the x axis `x` in `unit`; `source` names the file. A column
/// the plots have no curve for in `curves` is left out, and so is everything when the table's
/// rows cannot be placed on `x` (a crank-angle table on a time axis). On a crank-angle axis a
/// row is moved by whole turns into the axis's range where that is possible.
std::vector<OverlayCurve> overlayCurves(const kinematics::compare::Comparison& comparison, const QString& source,
                                        const std::vector<PlotCurve>& curves, const PlotXAxis& x, AngleUnit unit);

}  // namespace linkwright::ui
