#include "ui/plots/limit_markers.h"

#include "kinematics/solve/law_inverse.h"
#include "ui/colors.h"
#include "ui/plots/axis_range.h"
#include "ui/plots/chart_scale.h"
#include "ui/plots/series_visibility.h"

#include "kinematics/model/fourbar.h"

#include <QChart>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {
namespace {

constexpr double kMarkerSize = 8.0;  // the points', px at scale 1

namespace k = kinematics;

// The core reports the rocker angle in (−π, π]; the sweep's is unwrapped and may be whole
// turns away. Pick the turn nearest the sweep's value at sample `u` × (samples − 1), rounded
// (`u` in [0, 1]: where the limit lies along the grid or the time base).
double rockerAngleOnCurve(double rockerAngle, const k::SweepResult& sweep, double u) {
  const std::size_t n = sweep.size();
  const std::size_t link = k::fourbar::kRocker.index;
  if (n < 2 || link >= sweep.linkAngle.size() || sweep.linkAngle[link].size() != n || !std::isfinite(u))
    return rockerAngle;
  const auto j = static_cast<std::size_t>(std::lround(std::clamp(u, 0.0, 1.0) * static_cast<double>(n - 1)));
  if (!sweep.assembled(j)) return rockerAngle;
  const double turn = 2.0 * k::kPi;
  return rockerAngle + turn * std::round((sweep.linkAngle[link][j] - rockerAngle) / turn);
}

}  // namespace

QList<QPointF> limitMarkerPoints(const k::LimitReport& limits, const k::SweepResult& sweep, double fromDeg,
                                 double toDeg, AngleUnit unit) {
  QList<QPointF> points;
  for (const k::LimitPosition& limit : limits.positions) {
    const std::optional<double> xDeg = wrapIntoRange(k::radToDeg(limit.crankAngle), fromDeg, toDeg);
    if (!xDeg) continue;
    const double u = toDeg != fromDeg ? (*xDeg - fromDeg) / (toDeg - fromDeg) : 0.0;
    const double rocker = rockerAngleOnCurve(limit.rockerAngle, sweep, u);
    points.append(QPointF(toAngleUnit(k::degToRad(*xDeg), unit), toAngleUnit(rocker, unit)));
  }
  return points;
}

std::optional<QList<QPointF>> limitMarkerPointsInTime(const k::LimitReport& limits, const k::SweepResult& sweep,
                                                      const k::TimeBase& time, PlotAxis axis, AngleUnit unit,
                                                      qsizetype most) {
  QList<QPointF> points;
  const double span = time.toTime - time.fromTime;
  for (const k::LimitPosition& limit : limits.positions) {
    // One more than allowed tells "too many" from "exactly enough".
    const auto left = static_cast<std::size_t>(most - points.size() + 1);
    for (const double t : k::timesAtPosition(time, limit.crankAngle, left, 2.0 * k::kPi)) {
      const double u = span > 0.0 ? (t - time.fromTime) / span : 0.0;
      const double rocker = rockerAngleOnCurve(limit.rockerAngle, sweep, u);
      const double x = axis == PlotAxis::Time ? t : toAngleUnit(k::motionAt(time.law, t).position, unit);
      points.append(QPointF(x, toAngleUnit(rocker, unit)));
    }
    if (points.size() > most) return std::nullopt;
  }
  return points;
}

void LimitMarkers::setName(const QString& name) {
  if (m_points->name() != name) m_points->setName(name);
}

LimitMarkers::LimitMarkers(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis)
    : m_chart(chart), m_xAxis(xAxis), m_yAxis(yAxis), m_points(new QScatterSeries) {
  m_points->setObjectName(QStringLiteral("limit_points"));
  m_points->setName(tr("rocker limit"));
  m_points->setMarkerSize(kMarkerSize);
  m_points->setColor(colors().limitPoint);
  m_points->setBorderColor(Qt::white);
  m_points->setPointLabelsFormat(tr("limit"));
  m_points->setPointLabelsVisible(true);
  m_points->setPointLabelsClipping(true);
  chart->addSeries(m_points);
  m_points->attachAxis(xAxis);
  m_points->attachAxis(yAxis);
  setSeriesShown(m_chart, m_points, false, false);
}

LimitMarkers::~LimitMarkers() = default;

bool LimitMarkers::setPositions(const QList<QPointF>& points, bool showPoints) {
  QPen dashed(colors().limitLine, scaledPenWidth(m_chart, 1.0), Qt::DashLine);
  while (m_lines.size() < static_cast<std::size_t>(points.size())) {
    const QString name = QStringLiteral("limit_line_%1").arg(m_lines.size());
    m_lines.push_back(std::make_unique<VerticalMarker>(m_chart, m_xAxis, m_yAxis, dashed, name));
    m_lines.back()->setYSpan(m_lo, m_hi);
  }
  for (std::size_t i = 0; i < m_lines.size(); ++i)
    m_lines[i]->setX(i < static_cast<std::size_t>(points.size())
                         ? std::optional<double>(points[static_cast<qsizetype>(i)].x())
                         : std::nullopt);
  const bool pointsShown = showPoints && !points.isEmpty();
  const bool legendChanges = pointsShown != m_points->isVisible();
  m_points->replace(pointsShown ? points : QList<QPointF>{});
  // setChartScale passes over it while it is empty: it takes the chart's scale here.
  if (pointsShown) {
    m_points->setMarkerSize(kMarkerSize * chartScale(m_chart));
    m_points->setPointLabelsFont(scaledPointLabelsFont(m_chart, m_points));
  }
  setSeriesShown(m_chart, m_points, pointsShown, true);
  return legendChanges;
}

void LimitMarkers::setYSpan(double lo, double hi) {
  m_lo = lo;
  m_hi = hi;
  for (const auto& line : m_lines) line->setYSpan(lo, hi);
}

void LimitMarkers::raise() {
  for (const auto& line : m_lines) line->raise();
  const bool shown = m_points->isVisible();
  m_chart->removeSeries(m_points);
  m_chart->addSeries(m_points);
  m_points->attachAxis(m_xAxis);
  m_points->attachAxis(m_yAxis);
  setSeriesShown(m_chart, m_points, shown, true);
}

QList<double> LimitMarkers::lineXs() const {
  QList<double> xs;
  for (const auto& line : m_lines)
    if (line->x()) xs.append(*line->x());
  return xs;
}

}  // namespace linkwright::ui
