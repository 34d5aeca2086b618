#include "ui/plots/segmented_line.h"

#include "ui/plots/chart_scale.h"
#include "ui/plots/series_visibility.h"

#include <QChart>
#include <QGraphicsLayout>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <utility>

namespace linkwright::ui {
namespace {
constexpr double kCurveWidth = 2.0;
// Segments made with the curve: a linkage dragged into a rocking crank splits its curves into
// two runs (one gap inside the grid), and a series added to a chart mid-drag costs a frame (Qt
// Charts makes its item, legend marker and axis links, then lays out and repaints the chart).
// Not more: every series makes each later layout of its chart a little slower.
constexpr int kSegmentsMadeAhead = 2;
}  // namespace

SegmentedLine::SegmentedLine(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, Style style,
                             std::function<void(QLineSeries*)> onNewSegment)
    : m_chart(chart), m_xAxis(xAxis), m_yAxis(yAxis), m_style(std::move(style)),
      m_onNewSegment(std::move(onNewSegment)) {
  for (int i = 0; i < kSegmentsMadeAhead; ++i) addSegment();
}

QLineSeries* SegmentedLine::addSegment() {
  auto* segment = new QLineSeries;
  segment->setObjectName(m_style.key);
  segment->setName(m_style.name);
  segment->setPen(QPen(m_style.color, scaledPenWidth(m_chart, kCurveWidth)));
  m_chart->addSeries(segment);
  segment->attachAxis(m_xAxis);
  segment->attachAxis(m_yAxis);
  if (m_onNewSegment) m_onNewSegment(segment);
  m_segments.append(segment);
  setSeriesShown(m_chart, segment, false, false);
  return segment;
}

void SegmentedLine::setRuns(const SeriesRuns& runs, bool shown) {
  // Qt Charts does not lay the chart out again when a legend marker is shown or hidden: the
  // legend would keep its old size. (Any axis setter used to hide this by relaying out on
  // every update, which a drag cannot afford.)
  const bool legendChanges = shown != m_shown || m_runs.empty() != runs.empty();
  m_runs = runs;
  m_shown = shown;
  draw();
  if (legendChanges) m_chart->layout()->invalidate();
}

ScreenScale SegmentedLine::currentScale() const {
  const QRectF area = m_chart->plotArea();
  return {area.width() / (m_xAxis->max() - m_xAxis->min()), area.height() / (m_yAxis->max() - m_yAxis->min())};
}

void SegmentedLine::draw() {
  const qsizetype runCount = m_runs.runs.size();
  while (m_segments.size() < runCount) addSegment();
  m_drawnScale = currentScale();
  for (qsizetype i = 0; i < m_segments.size(); ++i) {
    QLineSeries* segment = m_segments[i];
    if (i < runCount) {
      simplifyForScreen(m_runs.runs[i], m_drawnScale, kCurveTolerancePx, m_vertices, m_scratch);
      segment->replace(m_vertices);
    } else if (segment->count() > 0) {
      segment->replace(QList<QPointF>{});
    }
    // A spare segment stays visible, only empty: showing a series re-shows its legend marker,
    // and each crossing into or out of a gap would then lay the chart out again.
    setSeriesShown(m_chart, segment, m_shown, i == 0);
  }
}

void SegmentedLine::rescale() {
  // Within 5 % of the drawn scale the error stays within 1.05 × the tolerance: not worth a redraw.
  constexpr double kRedrawRatio = 1.05;
  const ScreenScale now = currentScale();
  const auto differs = [](double a, double b) {
    return !(a > 0.0 && b > 0.0) || std::max(a, b) > kRedrawRatio * std::min(a, b);
  };
  if (m_runs.empty() || !now.usable()) return;
  if (differs(now.xPixelsPerUnit, m_drawnScale.xPixelsPerUnit) ||
      differs(now.yPixelsPerUnit, m_drawnScale.yPixelsPerUnit))
    draw();
}

QList<QPointF> SegmentedLine::samples() const {
  QList<QPointF> all;
  for (const QList<QPointF>& run : m_runs.runs) all += run;
  return all;
}

std::optional<QPointF> SegmentedLine::nearestSample(const QLineSeries* segment, qreal x) const {
  const qsizetype i = std::find(m_segments.begin(), m_segments.end(), segment) - m_segments.begin();
  if (i >= m_runs.runs.size() || m_runs.runs[i].isEmpty()) return std::nullopt;
  const QList<QPointF>& run = m_runs.runs[i];
  return *std::min_element(run.begin(), run.end(),
                           [x](QPointF a, QPointF b) { return std::abs(a.x() - x) < std::abs(b.x() - x); });
}

void SegmentedLine::removeFromChart() {
  for (QLineSeries* segment : m_segments) {
    m_chart->removeSeries(segment);
    delete segment;
  }
  m_segments.clear();
}

}  // namespace linkwright::ui
