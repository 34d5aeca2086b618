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
}  // namespace

SegmentedLine::SegmentedLine(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, Style style)
    : m_chart(chart), m_xAxis(xAxis), m_yAxis(yAxis), m_style(std::move(style)), m_legendEntry(new QLineSeries) {
  m_legendEntry->setObjectName(m_style.key);
  m_legendEntry->setName(m_style.name);
  QPen pen(m_style.color, scaledPenWidth(m_chart, kCurveWidth));
  pen.setStyle(m_style.dash);
  m_legendEntry->setPen(pen);
  m_chart->addSeries(m_legendEntry);
  m_legendEntry->attachAxis(m_xAxis);
  m_legendEntry->attachAxis(m_yAxis);
  setSeriesShown(m_chart, m_legendEntry, false, false);
  m_item = new CurveItem(m_chart, m_xAxis, m_yAxis, m_legendEntry);
  m_item->setObjectName(m_style.key);
  m_item->setVisible(false);
}

void SegmentedLine::setLegendName(const QString& name) {
  if (m_legendEntry->name() != name) m_legendEntry->setName(name);
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
  m_drawnScale = currentScale();
  QList<QList<QPointF>> vertices(m_runs.runs.size());
  for (qsizetype i = 0; i < m_runs.runs.size(); ++i)
    simplifyForScreen(m_runs.runs[i], m_drawnScale, kCurveTolerancePx, vertices[i], m_scratch);
  m_item->setRuns(std::move(vertices));
  if (m_item->isVisible() != m_shown) m_item->setVisible(m_shown);
  setSeriesShown(m_chart, m_legendEntry, m_shown, true);
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

std::optional<QPointF> SegmentedLine::nearestSample(qsizetype run, qreal x) const {
  if (run < 0 || run >= m_runs.runs.size() || m_runs.runs[run].isEmpty()) return std::nullopt;
  const QList<QPointF>& samples = m_runs.runs[run];
  return *std::min_element(samples.begin(), samples.end(),
                           [x](QPointF a, QPointF b) { return std::abs(a.x() - x) < std::abs(b.x() - x); });
}

void SegmentedLine::removeFromChart() {
  delete m_item;
  m_item = nullptr;
  m_chart->removeSeries(m_legendEntry);
  delete m_legendEntry;
  m_legendEntry = nullptr;
}

}  // namespace linkwright::ui
