#include "ui/plots/vertical_marker.h"

#include "ui/plots/series_visibility.h"

#include <QChart>
#include <QValueAxis>

namespace linkwright::ui {

VerticalMarker::VerticalMarker(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, const QPen& pen,
                               const QString& objectName)
    : m_chart(chart), m_series(new QLineSeries) {
  m_series->setObjectName(objectName);
  m_series->setPen(pen);
  chart->addSeries(m_series);
  m_series->attachAxis(xAxis);
  m_series->attachAxis(yAxis);
  setSeriesShown(m_chart, m_series, false, false);
}

void VerticalMarker::setX(std::optional<double> x) {
  if (x == m_x) return;
  m_x = x;
  update();
}

void VerticalMarker::setYSpan(double lo, double hi) {
  if (lo == m_lo && hi == m_hi) return;
  m_lo = lo;
  m_hi = hi;
  update();
}

void VerticalMarker::raise() {
  const QList<QAbstractAxis*> axes = m_series->attachedAxes();
  m_chart->removeSeries(m_series);  // hands the series back; addSeries takes it again
  m_chart->addSeries(m_series);
  for (QAbstractAxis* axis : axes) m_series->attachAxis(axis);
  update();
}

void VerticalMarker::update() {
  if (m_x) m_series->replace(QList<QPointF>{{*m_x, m_lo}, {*m_x, m_hi}});
  setSeriesShown(m_chart, m_series, m_x.has_value(), false);
}

}  // namespace linkwright::ui
