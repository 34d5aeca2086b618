#pragma once
// The rocker's limit (dead-centre) positions on the angle chart: a dashed vertical line at
// each limit's crank angle and a point labelled "limit" on the rocker-angle curve. The
// positions come from the core (DesignAnalysis::limits); this only places them on the axes.
// On a time base a limit is marked at every instant the law's crank passes its angle (found
// on the law itself, ui/document/drive_time.h), on a time axis or the input axis alike.

#include "ui/document/mechanism_document.h"
#include "ui/plots/angle_unit.h"
#include "ui/plots/vertical_marker.h"

#include "kinematics/analysis/limit_positions.h"
#include "kinematics/solve/sweep.h"

#include <QCoreApplication>
#include <QList>
#include <QPointF>

#include <memory>
#include <optional>
#include <vector>

class QChart;
class QScatterSeries;
class QValueAxis;

namespace linkwright::ui {

/// The limits as plot points: x = crank angle moved by whole turns into [fromDeg, toDeg],
/// y = rocker angle moved by whole turns next to the sweep's unwrapped rocker angle at that
/// crank angle (so the point sits on the plotted curve), both in `unit`. Limits whose crank
/// angle lies outside the grid are left out.
QList<QPointF> limitMarkerPoints(const kinematics::LimitReport& limits, const kinematics::SweepResult& sweep,
                                 double fromDeg, double toDeg, AngleUnit unit);

/// More limit crossings than this on a time base are not marked (the lines would hide the curves).
inline constexpr qsizetype kMostLimitMarkers = 48;

/// The limits on a time base: a point at every instant within `time` at which the law's crank
/// is at a limit's crank angle (any turn), in time order per limit. x = that instant (s) on the
/// time axis, or that crank angle (unwrapped, as the sweep's, in `unit`) on the input axis;
/// y = the rocker angle moved by whole turns next to the sweep's at the nearest sample.
/// `sweep` is on `time`'s base. nullopt if there are more than `most`: too many to mark.
std::optional<QList<QPointF>> limitMarkerPointsInTime(const kinematics::LimitReport& limits,
                                                      const kinematics::SweepResult& sweep,
                                                      const kinematics::TimeBase& time, PlotAxis axis, AngleUnit unit,
                                                      qsizetype most = kMostLimitMarkers);

class LimitMarkers {
  Q_DECLARE_TR_FUNCTIONS(LimitMarkers)
public:
  /// Adds the markers' series to `chart` (which owns them) on the given axes.
  LimitMarkers(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis);
  ~LimitMarkers();
  LimitMarkers(const LimitMarkers&) = delete;
  LimitMarkers& operator=(const LimitMarkers&) = delete;

  /// A line at each point's x; the labelled points themselves only if `showPoints` (the
  /// rocker curve is shown). Returns whether their legend entry appeared or went.
  bool setPositions(const QList<QPointF>& points, bool showPoints);
  /// The points' name in the legend ("rocker limit" at first).
  void setName(const QString& name);
  /// The y extent of the lines (the value axis range).
  void setYSpan(double lo, double hi);
  /// Puts the markers back on top of the chart's series and legend (after curves were added).
  void raise();

  QScatterSeries* points() const { return m_points; }
  /// The x of every line shown, in order.
  QList<double> lineXs() const;

private:
  QChart* m_chart;
  QValueAxis* m_xAxis;
  QValueAxis* m_yAxis;
  QScatterSeries* m_points;
  std::vector<std::unique_ptr<VerticalMarker>> m_lines;
  double m_lo = 0.0;
  double m_hi = 1.0;
};

}  // namespace linkwright::ui
