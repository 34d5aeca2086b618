#include "ui/plots/segmented_line.h"

#include "ui/plots/series_visibility.h"

#include <QChart>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

#include <utility>

namespace linkwright::ui {
namespace {
constexpr double kCurveWidth = 2.0;
}  // namespace

SegmentedLine::SegmentedLine(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, Style style,
                             std::function<void(QLineSeries*)> onNewSegment)
    : m_chart(chart), m_xAxis(xAxis), m_yAxis(yAxis), m_style(std::move(style)),
      m_onNewSegment(std::move(onNewSegment)) {
  addSegment();
}

QLineSeries* SegmentedLine::addSegment() {
  auto* segment = new QLineSeries;
  segment->setObjectName(m_style.key);
  segment->setName(m_style.name);
  segment->setPen(QPen(m_style.color, kCurveWidth));
  m_chart->addSeries(segment);
  segment->attachAxis(m_xAxis);
  segment->attachAxis(m_yAxis);
  if (m_onNewSegment) m_onNewSegment(segment);
  m_segments.append(segment);
  setSeriesShown(m_chart, segment, false, false);
  return segment;
}

void SegmentedLine::setRuns(const SeriesRuns& runs, bool shown) {
  while (m_segments.size() < runs.runs.size()) addSegment();
  for (qsizetype i = 0; i < m_segments.size(); ++i) {
    QLineSeries* segment = m_segments[i];
    if (i < runs.runs.size()) segment->replace(runs.runs[i]);
    else if (segment->count() > 0) segment->replace(QList<QPointF>{});
    setSeriesShown(m_chart, segment, shown && (i == 0 || i < runs.runs.size()), i == 0);
  }
}

void SegmentedLine::removeFromChart() {
  for (QLineSeries* segment : m_segments) {
    m_chart->removeSeries(segment);
    delete segment;
  }
  m_segments.clear();
}

}  // namespace linkwright::ui
